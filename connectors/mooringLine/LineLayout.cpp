#include "mooringLine/LineLayout.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "mooringLine/MooringLine.hpp"

namespace connectors {

namespace {

constexpr double pi = 3.14159265358979323846;

//- Section k's constants (k = 0: the parameters' own line), written as
//  the uniform line's force model wrote them
LineLayout::Section section(const MooringLineParameters& p, std::size_t k,
                            double w0)
{
    const LineSection s = p.section(k);
    const double rho = p.waterDensity, d = s.diameter;
    LineLayout::Section c;
    c.segments = s.segments;
    c.l = s.length / s.segments;
    c.inverseL = 1.0 / c.l;
    c.EA = s.EA;
    c.BA = s.axialDamping;
    c.massPerLength = s.massPerLength;
    c.diameter = d;
    c.area = 0.25 * pi * d * d;
    c.w = k == 0 ? w0 : (s.massPerLength - rho * c.area) * p.gravity;
    c.dryWeight = s.massPerLength * p.gravity;
    c.buoyancy = rho * c.area * p.gravity;
    c.cn = 0.5 * rho * d * s.normalDrag;
    c.ct = 0.5 * rho * pi * d * s.tangentialDrag;
    c.addedN = s.normalAddedMass * rho * c.area * c.l;
    c.addedT = s.tangentialAddedMass * rho * c.area * c.l;
    c.flowInertiaN = rho * c.area * (1.0 + s.normalAddedMass);
    c.flowInertiaT = rho * c.area * (1.0 + s.tangentialAddedMass);
    return c;
}

//- Depth at which the seabed's stiffness kb over the contact width
//  `support` [N/m2 per m] carries the weight `w` [N/m]; the least double
//  where it carries nothing (the damping then acts from the floor on)
double restDepth(double w, double support)
{
    return support > 0.0 && w > 0.0 ? w / support
                                    : std::numeric_limits<double>::min();
}

//- A joint point's own seabed contact area [m2] for its net weight J [N]
//  beside sections a and b: J times the smaller d/w of the two (the deeper
//  rest depth w/(kb d)), so that the point sinks as deep as the line
//  there and its support does not shrink with the segments; 0 for a buoy
//  (J <= 0) and beside two sections lighter than water
double pointContact(double J, const LineLayout::Section& a,
                    const LineLayout::Section& b)
{
    double widthPerWeight = 0.0; // d/w [m/(N/m)]
    for (const LineLayout::Section* s : {&a, &b}) {
        if (s->w > 0.0 && s->diameter > 0.0) {
            const double r = s->diameter / s->w;
            widthPerWeight
                = widthPerWeight > 0.0 ? std::min(widthPerWeight, r) : r;
        }
    }
    return J > 0.0 ? J * widthPerWeight : 0.0;
}

LineLayout::Node::Piece piece(int k, const LineLayout::Section& s, double share)
{
    LineLayout::Node::Piece p;
    p.section = k;
    p.share = share;
    p.diameter = s.diameter;
    p.dryWeight = s.dryWeight;
    p.buoyancy = s.buoyancy;
    p.cn = s.cn;
    p.ct = s.ct;
    return p;
}

} // namespace

LineLayout lineLayout(const MooringLineParameters& p, double w)
{
    LineLayout L;
    const std::size_t n = 1 + p.sections.size();
    for (std::size_t k = 0; k < n; ++k) {
        LineLayout::Section s = section(p, k, w);
        s.firstSegment = L.N;
        L.N += s.segments;
        L.segmentSection.insert(L.segmentSection.end(), std::size_t(s.segments),
                                int(k));
        L.sections.push_back(s);
    }
    const int N = L.N;
    L.arc.assign(std::size_t(N + 1), 0.0);
    for (int j = 0; j < N; ++j) {
        L.arc[std::size_t(j + 1)] = L.arc[std::size_t(j)] + L.ofSegment(j).l;
    }
    L.length = p.length;
    L.absoluteWeight = std::abs(w) * p.length;
    L.shortest = L.sections[0].l;
    for (std::size_t k = 1; k < n; ++k) {
        const LineSection& s = p.sections[k - 1];
        L.length += s.length;
        L.absoluteWeight += std::abs(L.sections[k].w) * s.length
            + std::abs((s.joint.mass - p.waterDensity * s.joint.volume)
                       * p.gravity);
        L.shortest = std::min(L.shortest, L.sections[k].l);
    }
    L.nodes.resize(std::size_t(N + 1));
    const double kb = p.seabedStiffness;
    for (int i = 0; i <= N; ++i) {
        LineLayout::Node& node = L.nodes[std::size_t(i)];
        const int below = std::max(i - 1, 0), above = std::min(i, N - 1);
        const int a = L.segmentSection[std::size_t(below)];
        const int b = L.segmentSection[std::size_t(above)];
        const LineLayout::Section& sa = L.sections[std::size_t(a)];
        const LineLayout::Section& sb = L.sections[std::size_t(b)];
        if (a == b) {
            // inside a section, or an end: as the uniform line
            const bool end = i == 0 || i == N;
            node.piece[0] = piece(a, sa, end ? 0.5 * sa.l : sa.l);
            node.ramp = sa.l;
            node.restDepth = restDepth(sa.w, kb * sa.diameter);
            node.surfaceStiffness = p.waterDensity * 0.25 * pi * sa.diameter
                * sa.diameter * p.gravity;
            node.mass = end ? 0.0 : sa.massPerLength * sa.l;
            node.addedN = end ? 0.0 : sa.addedN;
            node.addedT = end ? 0.0 : sa.addedT;
            node.flowInertiaN = sa.flowInertiaN * node.piece[0].share;
            node.flowInertiaT = sa.flowInertiaT * node.piece[0].share;
            continue;
        }
        // the joint of sections a and b = a + 1, and its point
        const LinePoint& point = p.sections[std::size_t(b - 1)].joint;
        node.pieces = 2;
        node.piece[0] = piece(a, sa, 0.5 * sa.l);
        node.piece[1] = piece(b, sb, 0.5 * sb.l);
        node.point = b - 1;
        node.ramp = 0.5 * (sa.l + sb.l);
        node.pointWeight = point.mass * p.gravity;
        node.pointBuoyancy = p.waterDensity * point.volume * p.gravity;
        node.pointDrag = 0.5 * p.waterDensity * point.dragArea;
        node.pointContact
            = pointContact(node.pointWeight - node.pointBuoyancy, sa, sb);
        node.restDepth
            = restDepth(sa.w * node.piece[0].share + sb.w * node.piece[1].share
                            + node.pointWeight - node.pointBuoyancy,
                        node.contact(kb));
        node.surfaceStiffness
            = (sa.buoyancy * node.piece[0].share
               + sb.buoyancy * node.piece[1].share + node.pointBuoyancy)
            / node.ramp;
        const double pointAdded
            = point.addedMass * p.waterDensity * point.volume;
        node.mass = 0.5 * (sa.massPerLength * sa.l + sb.massPerLength * sb.l)
            + point.mass;
        node.addedN = 0.5 * (sa.addedN + sb.addedN) + pointAdded;
        node.addedT = 0.5 * (sa.addedT + sb.addedT) + pointAdded;
        const double pointInertia
            = (1.0 + point.addedMass) * p.waterDensity * point.volume;
        node.flowInertiaN = sa.flowInertiaN * node.piece[0].share
            + sb.flowInertiaN * node.piece[1].share + pointInertia;
        node.flowInertiaT = sa.flowInertiaT * node.piece[0].share
            + sb.flowInertiaT * node.piece[1].share + pointInertia;
    }
    return L;
}

double LineLayout::nodeCoordinate(double fromQ) const
{
    if (sections.size() == 1) {
        return N * fromQ;
    }
    const double s = std::clamp(fromQ, 0.0, 1.0) * length;
    const int j = int(std::upper_bound(arc.begin() + 1, arc.end() - 1, s)
                      - (arc.begin() + 1));
    return std::min(j + (s - arc[std::size_t(j)]) / ofSegment(j).l, double(N));
}

std::vector<int> LineLayout::jointNodes() const
{
    std::vector<int> joints;
    for (std::size_t k = 1; k < sections.size(); ++k) {
        joints.push_back(sections[k].firstSegment);
    }
    return joints;
}

std::vector<double> LineLayout::sectionEnds(const std::vector<double>& T,
                                            bool upper) const
{
    std::vector<double> ends;
    for (const Section& s : sections) {
        ends.push_back(
            T[std::size_t(s.firstSegment + (upper ? s.segments - 1 : 0))]);
    }
    return ends;
}

} // namespace connectors
