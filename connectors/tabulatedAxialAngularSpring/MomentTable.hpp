// The moment table of the tabulatedAxialAngularSpring law: OpenFOAM's
// interpolationTable<scalar> (v1912, v2312) as that restraint looks it up,
// linear between points of strictly increasing angle, with its outOfBounds
// behaviours, and the integral of the same function (exact: piecewise
// quadratic), which gives the spring's potential energy.
//
// With x_1 < ... < x_n the angles and y_1 ... y_n the moments, the value
// at x (OpenFOAM's interpolateValue):
//
//   x_1 <= x < x_n: y_i + (y_{i+1} - y_i) (x - x_i) / (x_{i+1} - x_i),
//     x_i <= x < x_{i+1}
//   x < x_1:   y_1                  (error: refused, warn and clamp: y_1,
//                                    repeat: y_1, see below)
//   x >= x_n:  y_n                  (error: refused, warn and clamp: y_n,
//                                    repeat: the value at
//                                    fmod(x - x_1, x_n - x_1) + x_1)
//
// OpenFOAM's repeat takes fmod of x - x_1 < 0 below the table, which stays
// below x_1, and so gives y_1 there; at x = x_n it gives y_1 too. Both are
// reproduced. Its error and warn apply at x = x_n already.
#ifndef CONNECTORS_TABULATEDAXIALANGULARSPRING_MOMENTTABLE_HPP
#define CONNECTORS_TABULATEDAXIALANGULARSPRING_MOMENTTABLE_HPP

#include <vector>

namespace connectors {

//- OpenFOAM's outOfBounds (bounds::repeatableBounding), in its order
enum class OutOfBounds { error, warn, clamp, repeat };

class MomentTable {
public:
    //- At least 2 points, finite, the angles strictly increasing; throws
    //  ParameterError naming table.points, table.angle[k] or
    //  table.moment[k] of `law` otherwise; angleUnit names the angles' unit
    MomentTable(const char* law, std::vector<double> angle,
                std::vector<double> moment, const char* angleUnit,
                OutOfBounds outOfBounds);

    //- Whether x lies where outOfBounds applies: x < x_1 or x >= x_n
    bool outside(double x) const;

    //- The value at x, as OpenFOAM's (error: as clamp, the caller refuses
    //  x outside)
    double value(double x) const;

    //- The integral of value from x_1 to x (below x_1 negative)
    double integral(double x) const;

    double first() const { return angle_.front(); }
    double last() const { return angle_.back(); }

private:
    //- The integral of the linear interpolation from x_1 to x, x_1 <= x <= x_n
    double integralInside(double x) const;

    std::vector<double> angle_, moment_;
    OutOfBounds outOfBounds_;
    //- The integral over the whole table, x_1 to x_n
    double whole_ = 0.0;
};

} // namespace connectors

#endif
