#include "FlowHistory.hpp"

#include <algorithm>

namespace mooringLineFmu {

using connectors::Vector3;

std::vector<Vector3> FlowHistory::acceleration(const std::vector<Vector3>& U,
                                               double time) const
{
    const double h = time - time_;
    if (!(h > 0.0) || (U.empty() && flow_.empty())) {
        return {};
    }
    std::vector<Vector3> a(std::size_t(points_), Vector3::Zero());
    bool any = false;
    for (std::size_t k = 0; k < a.size(); ++k) {
        const Vector3 now = U.empty() ? Vector3::Zero() : U[k];
        const Vector3 before = flow_.empty() ? Vector3::Zero() : flow_[k];
        a[k] = (now - before) / h;
        any = any || !a[k].isZero(0.0);
    }
    if (!any) {
        a.clear();
    }
    return a;
}

void FlowHistory::save(std::vector<double>& out) const
{
    out.push_back(time_);
    for (const std::vector<Vector3>* x : {&flow_, &acceleration_}) {
        for (int k = 0; k < points_; ++k) {
            for (int axis = 0; axis < 3; ++axis) {
                out.push_back(x->empty() ? 0.0 : (*x)[std::size_t(k)][axis]);
            }
        }
    }
}

void FlowHistory::restore(const double* data)
{
    time_ = data[0];
    // all zero: none (acceleration() gives none for no change)
    const auto points = [this](const double* u, std::vector<Vector3>& x) {
        x.clear();
        if (std::any_of(u, u + 3 * points_,
                        [](double v) { return v != 0.0; })) {
            for (int k = 0; k < points_; ++k) {
                x.emplace_back(u[3 * k], u[3 * k + 1], u[3 * k + 2]);
            }
        }
    };
    points(data + 1, flow_);
    points(data + 1 + 3 * points_, acceleration_);
}

} // namespace mooringLineFmu
