// The flow inputs of mooringLine.fmu's last step, kept in its state: the
// flow's acceleration over a step is their change since then,
// a = (U(t) - U(t_prev))/(t - t_prev) at each shape point.
#ifndef FMU_MOORINGLINE_FLOWHISTORY_HPP
#define FMU_MOORINGLINE_FLOWHISTORY_HPP

#include <cstddef>
#include <vector>

#include "common/Kinematics.hpp"

namespace mooringLineFmu {

class FlowHistory {
public:
    //- Over `points` shape points
    explicit FlowHistory(int points) : points_(points) { }

    //- The flow inputs U (empty: all zero) of the step from `time` [s]
    void record(double time, const std::vector<connectors::Vector3>& U)
    {
        time_ = time;
        flow_ = U;
    }

    //- The acceleration [m/s2] over a step from `time` with the inputs U:
    //  their change since the recorded step over its length; empty when
    //  none (at or before the recorded time, or no change)
    std::vector<connectors::Vector3>
    acceleration(const std::vector<connectors::Vector3>& U, double time) const;

    //- Values in a saved state: the time, then 3 per point
    std::size_t size() const { return 1 + 3 * std::size_t(points_); }
    //- Appends them to `out`
    void save(std::vector<double>& out) const;
    //- Restores them from `data` (size() values)
    void restore(const double* data);

private:
    int points_;
    double time_ = 0.0;
    std::vector<connectors::Vector3> flow_;
};

} // namespace mooringLineFmu

#endif
