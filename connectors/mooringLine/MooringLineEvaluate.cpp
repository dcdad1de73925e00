// MooringLine (MooringLine.hpp): the water's motion along the line, the
// loads on the bodies and the diagnostics of a state.
#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "common/AxialGeometry.hpp"
#include "common/ConnectorError.hpp"
#include "mooringLine/LineForces.hpp"
#include "mooringLine/MooringLine.hpp"

namespace connectors {

namespace {
const char* const lawName = "mooringLine";
constexpr double pi = 3.14159265358979323846;
} // namespace

void MooringLine::alongLine(const std::vector<Vector3>& points,
                            std::vector<Vector3>& atNodes) const
{
    // node i is (N - i)/N of the line from P (its unstretched arc from P
    // over L with sections): between points k and k + 1
    const LineLayout& L = layout_;
    const int N = L.N;
    const int last = int(points.size()) - 1;
    atNodes.resize(std::size_t(N + 1));
    for (int i = 0; i <= N; ++i) {
        const double u = L.sections.size() == 1
            ? double(N - i) * last / N
            : (L.length - L.arc[std::size_t(i)]) / L.length * last;
        const int k = std::min(int(u), last - 1);
        const double f01 = u - k;
        atNodes[std::size_t(i)] = (1.0 - f01) * points[std::size_t(k)]
            + f01 * points[std::size_t(k + 1)];
    }
}

void MooringLine::waterMotion(const std::vector<Vector3>& flow,
                              const std::vector<Vector3>& flowAcceleration,
                              WaterMotion& water) const
{
    const MooringLineParameters& p = parameters_;
    water.current
        = !p.currentSurface.isZero(0.0) || !p.currentSeabed.isZero(0.0);
    const auto check = [](const std::vector<Vector3>& points,
                          const char* what) {
        if (points.size() == 1) {
            throw std::invalid_argument(std::string("mooringLine: the ") + what
                                        + " needs 0 or at least 2 points");
        }
        for (std::size_t k = 0; k < points.size(); ++k) {
            if (!points[k].allFinite()) {
                throw UndefinedStateError(
                    std::string("mooringLine: the ") + what + " at shape point "
                    + std::to_string(k + 1) + " is not finite");
            }
        }
    };
    check(flow, "flow velocity");
    check(flowAcceleration, "flow acceleration");
    if (!flow.empty() && !flowAcceleration.empty()
        && flow.size() != flowAcceleration.size()) {
        throw std::invalid_argument(
            "mooringLine: the flow's velocity and acceleration need the same "
            "points");
    }
    if (flow.empty()) {
        water.flow.clear();
    } else {
        alongLine(flow, water.flow);
    }
    if (flowAcceleration.empty()) {
        water.flowAcceleration.clear();
    } else {
        alongLine(flowAcceleration, water.flowAcceleration);
    }
}

MooringLineOutput MooringLine::evaluate(
    const MooringLineState& state, const BodyKinematics& A,
    const BodyKinematics& B, int shapePoints, const std::vector<Vector3>& flow,
    const std::vector<Vector3>& flowAcceleration, Detail detail) const
{
    requireFiniteInputs(lawName, A, B);
    const MooringLineParameters& p = parameters_;
    const LineLayout& L = layout_;
    const int N = L.N;
    if (state.nodes.size() != 6 * std::size_t(N - 1)) {
        throw std::invalid_argument("mooringLine: state does not fit the line");
    }
    const AxialGeometry g = axialGeometry(A, B, p.p_AoP_A, p.p_BoQ_B);
    // The forces of the last trapezoidal step's end (or evaluation) where
    // they are those of the same numbers, else evaluated; kept in
    // lastEvaluated_ for the next step's start
    auto& last = lastEvaluated_;
    std::vector<Vector3>& nodesR = last.nextR;
    std::vector<Vector3>& nodesV = last.nextV;
    nodesR.resize(std::size_t(N + 1));
    nodesV.resize(std::size_t(N + 1));
    unpack(state.nodes, N, nodesR, nodesV);
    nodesR[0] = attachment(B, p.p_BoQ_B);
    nodesR[N] = attachment(A, p.p_AoP_A);
    nodesV[0] = attachmentVelocity(B, p.p_BoQ_B);
    nodesV[N] = attachmentVelocity(A, p.p_AoP_A);
    WaterMotion& water = last.nextWater;
    waterMotion(flow, flowAcceleration, water);
    const double zb = nodesR[0][2];
    if (!(sameBits(nodesR, last.r) && sameBits(nodesV, last.v) && last.zb == zb
          && sameBits(water.flow, last.water.flow)
          && sameBits(water.flowAcceleration, last.water.flowAcceleration))) {
        last.r.swap(nodesR);
        last.v.swap(nodesV);
        last.zb = zb;
        std::swap(last.water, water);
        nodeForces(p, L, last.r, last.v, zb, last.f, &last.water);
    }
    const std::vector<Vector3>& r = last.r;
    const NodeForces& f = last.f;

    MooringLineOutput out;
    ConnectorResult& res = out.loads;
    // The end nodes' own forces (their half segments' weight, buoyancy,
    // drag, seabed) act on the bodies
    res.A.f_W = -f.T[N - 1] * f.q[N - 1] + f.external[N];
    res.B.f_W = f.T[0] * f.q[0] + f.external[0];
    if (p.endInertia) {
        // and their inertia: half a segment's mass and added mass moving
        // with the attachment point
        const auto inertia = [&](int i, const Vector3& a) {
            const LineSection s = p.section(i == 0 ? 0 : L.sections.size() - 1);
            const double l = s.length / s.segments;
            const double area = 0.25 * pi * s.diameter * s.diameter;
            const double added
                = 0.5 * l * p.waterDensity * area * f.submerged[std::size_t(i)];
            const Vector3& t = f.tangent[std::size_t(i)];
            const double along = a.dot(t);
            return Vector3(0.5 * l * s.massPerLength * a
                           + added * s.normalAddedMass * (a - along * t)
                           + added * s.tangentialAddedMass * along * t);
        };
        res.A.f_W -= inertia(N, state.aP);
        res.B.f_W -= inertia(0, state.aQ);
    }
    res.A.m_Ko_W = g.p_AoP_W.cross(res.A.f_W);
    res.B.m_Ko_W = g.p_BoQ_W.cross(res.B.f_W);
    res.length = g.length;
    res.lengthRate = g.lengthRate;
    out.fairleadTension = res.A.f_W.norm();
    out.anchorTension = res.B.f_W.norm();
    res.tension = out.fairleadTension;
    res.potentialEnergy = f.strainEnergy + f.seabedEnergy + f.gravityEnergy;
    res.dissipatedPower = std::max(f.dissipatedPower, 0.0);
    // l times the grounded segments (both nodes on the seabed), section
    // by section
    const auto grounded
        = [&](int i) { return i == 0 || i == N || r[i][2] <= r[0][2]; };
    for (const LineLayout::Section& c : L.sections) {
        int count = 0;
        for (int j = c.firstSegment;
             p.seabedContact && j < c.firstSegment + c.segments; ++j) {
            count += grounded(j) && grounded(j + 1);
        }
        out.groundedLength += c.l * count;
    }
    out.H = std::hypot(res.A.f_W[0], res.A.f_W[1]);
    out.V = -res.A.f_W[2];
    if (shapePoints == 1 || shapePoints < 0) {
        throw std::invalid_argument(
            "mooringLine: shapePoints must be 0 or >= 2");
    }
    if (detail == Detail::loads) {
        return out;
    }
    for (int k = 0; k < shapePoints; ++k) {
        const double u = L.nodeCoordinate(1.0 - double(k) / (shapePoints - 1));
        const int i = std::min(int(u), N - 1);
        const double f01 = u - i;
        out.shape.push_back((1.0 - f01) * r[i] + f01 * r[i + 1]);
        // tension: anchorTension at node 0, T_j at u = j + 1/2,
        // fairleadTension at node N, linear between
        double T = 0.0;
        if (u <= 0.5) {
            T = out.anchorTension + 2.0 * u * (f.T[0] - out.anchorTension);
        } else if (u >= N - 0.5) {
            T = f.T[N - 1]
                + 2.0 * (u - (N - 0.5)) * (out.fairleadTension - f.T[N - 1]);
        } else {
            const int j = std::min(int(u - 0.5), N - 2);
            const double g = u - 0.5 - j;
            T = (1.0 - g) * f.T[j] + g * f.T[j + 1];
        }
        out.shapeTension.push_back(T);
    }
    out.sectionLowerTension = L.sectionEnds(f.T, false);
    out.sectionUpperTension = L.sectionEnds(f.T, true);
    for (const int i : L.jointNodes()) {
        out.joints.push_back(r[std::size_t(i)]);
    }
    out.sectionKineticEnergy = kineticEnergy(L, last.v, f);
    for (const double K : out.sectionKineticEnergy) {
        out.kineticEnergy += K;
    }
    return out;
}

CvodeBdf::Statistics MooringLine::statistics() const
{
    if (!integrator_) {
        return trapezoidStatistics_;
    }
    CvodeBdf::Statistics s = integrator_->statistics();
    s.rhsEvaluations += energyEvaluations_;
    return s;
}

} // namespace connectors
