#include "tabulatedAxialAngularSpring/MomentTable.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "common/ConnectorError.hpp"

namespace connectors {

namespace {

std::string indexed(const char* name, std::size_t i)
{
    return std::string(name) + "[" + std::to_string(i + 1) + "]";
}

} // namespace

MomentTable::MomentTable(const char* law, std::vector<double> angle,
                         std::vector<double> moment, const char* angleUnit,
                         OutOfBounds outOfBounds)
    : angle_(std::move(angle)), moment_(std::move(moment)),
      outOfBounds_(outOfBounds)
{
    const std::size_t n = angle_.size();
    if (n < 2 || moment_.size() != n) {
        throw ParameterError(Refusal::outOfRange, law, "table.points",
                             double(n), "1",
                             "an integer >= 2, one moment per angle");
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (!std::isfinite(angle_[i])) {
            throw ParameterError(Refusal::notFinite, law,
                                 indexed("table.angle", i), angle_[i],
                                 angleUnit, "finite");
        }
        if (i > 0 && !(angle_[i] > angle_[i - 1])) {
            throw ParameterError(Refusal::inconsistent, law,
                                 indexed("table.angle", i), angle_[i],
                                 angleUnit,
                                 "> " + indexed("table.angle", i - 1) + " = "
                                     + formatValue(angle_[i - 1])
                                     + ": the angles strictly increasing");
        }
        if (!std::isfinite(moment_[i])) {
            throw ParameterError(Refusal::notFinite, law,
                                 indexed("table.moment", i), moment_[i], "N.m",
                                 "finite");
        }
    }
    whole_ = integralInside(last());
}

bool MomentTable::outside(double x) const
{
    return x < first() || x >= last();
}

double MomentTable::value(double x) const
{
    if (outside(x)) {
        if (outOfBounds_ != OutOfBounds::repeat) {
            return x < first() ? moment_.front() : moment_.back();
        }
        x = std::fmod(x - first(), last() - first()) + first();
    }
    // OpenFOAM's search: the last point at or below x, the next above it
    std::size_t lo = 0, hi = 0;
    for (std::size_t i = 0; i < angle_.size(); ++i) {
        if (x >= angle_[i]) {
            lo = hi = i;
        } else {
            hi = i;
            break;
        }
    }
    if (lo == hi) {
        return moment_[hi];
    }
    return moment_[lo]
        + (moment_[hi] - moment_[lo]) * (x - angle_[lo])
        / (angle_[hi] - angle_[lo]);
}

double MomentTable::integralInside(double x) const
{
    double sum = 0.0;
    for (std::size_t i = 0; i + 1 < angle_.size() && x > angle_[i]; ++i) {
        const double x1 = std::min(x, angle_[i + 1]);
        const double y1 = moment_[i]
            + (moment_[i + 1] - moment_[i]) * (x1 - angle_[i])
                / (angle_[i + 1] - angle_[i]);
        sum += 0.5 * (x1 - angle_[i]) * (moment_[i] + y1);
    }
    return sum;
}

double MomentTable::integral(double x) const
{
    if (x < first()) {
        return moment_.front() * (x - first());
    }
    if (x < last()) {
        return integralInside(x);
    }
    if (outOfBounds_ != OutOfBounds::repeat) {
        return whole_ + moment_.back() * (x - last());
    }
    // Whole periods of the table, then the rest of one
    const double span = last() - first();
    const double periods = std::floor((x - first()) / span);
    const double rest = std::clamp(x - first() - periods * span, 0.0, span);
    return periods * whole_ + integralInside(first() + rest);
}

} // namespace connectors
