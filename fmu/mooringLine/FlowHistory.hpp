// The flow inputs of mooringLine.fmu's last step and the flow's
// acceleration it was taken with, kept in its state: the flow's
// acceleration over a step is the inputs' change since then,
// a = (U(t) - U(t_prev))/(t - t_prev) at each shape point; the last step's
// serves the outputs computed when read (completeOutputs).
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
    //  and the acceleration `a` (acceleration(); empty: none) it took
    void record(double time, const std::vector<connectors::Vector3>& U,
                const std::vector<connectors::Vector3>& a = {})
    {
        time_ = time;
        flow_ = U;
        acceleration_ = a;
    }

    //- The acceleration of the recorded step (empty: none)
    const std::vector<connectors::Vector3>& stepAcceleration() const
    {
        return acceleration_;
    }

    //- The acceleration [m/s2] over a step from `time` with the inputs U:
    //  their change since the recorded step over its length; empty when
    //  none (at or before the recorded time, or no change)
    std::vector<connectors::Vector3>
    acceleration(const std::vector<connectors::Vector3>& U, double time) const;

    //- Values in a saved state: the time, then 3 per point of the flow,
    //  then 3 per point of the acceleration
    std::size_t size() const { return 1 + 6 * std::size_t(points_); }
    //- Appends them to `out`
    void save(std::vector<double>& out) const;
    //- Restores them from `data` (size() values)
    void restore(const double* data);

private:
    int points_;
    double time_ = 0.0;
    std::vector<connectors::Vector3> flow_, acceleration_;
};

} // namespace mooringLineFmu

#endif
