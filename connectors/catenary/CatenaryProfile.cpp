#include "catenary/CatenaryProfile.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include "catenary/CatenarySections.hpp"
#include "catenary/CatenarySpan.hpp"
#include "common/ConnectorError.hpp"

namespace connectors {

namespace {

using catenarySpan::asinhOverX;
using catenarySpan::Span;
using catenarySpan::suspendedSpan;

//- Anchored line with a grounded part (w > 0, V < wL)
Span touchdownSpan(const CatenaryLine& line, double H, double V)
{
    const double L = line.length, EA = line.EA, w = line.weight;
    const double Ls = V / w, Lb = L - Ls, a = V / H;
    const double sa = std::hypot(1.0, a);
    Span out;
    out.x = Lb + Ls * asinhOverX(a) + H * L / EA;
    out.z = Ls * a / (sa + 1.0) + V * V / (2.0 * EA * w);
    out.xH = (std::asinh(a) - a / sa) / w + L / EA;
    out.xV = -(1.0 - 1.0 / sa) / w;
    out.zH = (1.0 / sa - 1.0) / w;
    out.zV = (a / sa) / w + V / (EA * w);
    const double CB = line.seabedFriction;
    if (CB > 0.0) {
        const double c = CB * w, u = Lb - H / c, mu = std::max(u, 0.0);
        out.x += c / (2.0 * EA) * (-Lb * Lb + u * mu);
        out.xH += -mu / EA;
        out.xV += CB / EA * (Lb - mu);
    }
    return out;
}

bool grounded(const CatenaryLine& line, double V)
{
    if (!line.sections.empty()) {
        return catenarySections::grounded(line, V);
    }
    return line.seabedContact && line.weight > 0.0
        && V < line.weight * line.length;
}

Span span(const CatenaryLine& line, double H, double V)
{
    if (!line.sections.empty()) {
        return catenarySections::span(line, H, V);
    }
    if (grounded(line, V)) {
        return touchdownSpan(line, H, V);
    }
    return suspendedSpan(line.length, line.EA, line.weight, H,
                         V - line.weight * line.length);
}

//- Unstretched length hanging vertically from the seabed to height z
//  (z = Ls + w Ls^2/(2EA)), w > 0, z >= 0
double verticalHangLength(const CatenaryLine& line, double z)
{
    return 2.0 * z / (1.0 + std::sqrt(1.0 + 2.0 * line.weight * z / line.EA));
}

//- First Newton iterate without a previous solution (after MoorDyn's
//  Catenary routine, mirrored for a buoyant line)
CatenaryGuess coldGuess(const CatenaryLine& line, double x, double z)
{
    const double L = line.length, w = line.weight;
    const double chord = std::hypot(x, z);
    const double sign = w < 0.0 ? -1.0 : 1.0;
    const double W = std::abs(w), Z = sign * z;
    CatenaryGuess g;
    if (chord >= L || W == 0.0) {
        const double T = line.EA * std::max(chord / L - 1.0, 1e-6) + W * L;
        g.H = T * x / chord;
        g.V = T * z / chord + 0.5 * w * L;
        return g;
    }
    const double lambda
        = std::sqrt(3.0 * std::max((L * L - Z * Z) / (x * x) - 1.0, 1e-12));
    g.H = std::max(0.5 * W * x / lambda, 1e-6 * W * L);
    g.V = sign * 0.5 * W * (Z / std::tanh(lambda) + L);
    return g;
}

//- Newton's first iterate: a usable previous solution, else a cold guess
//  (for a line of sections that of its uniform equivalent)
CatenaryGuess start(const CatenaryGuess* guess, const CatenaryLine& line,
                    double x, double z)
{
    if (guess != nullptr && guess->H > 0.0 && std::isfinite(guess->H)
        && std::isfinite(guess->V)) {
        return *guess;
    }
    return line.sections.empty()
        ? coldGuess(line, x, z)
        : coldGuess(catenarySections::equivalentUniform(line), x, z);
}

void fillEnds(const CatenaryLine& line, CatenarySolution& s)
{
    if (!line.sections.empty()) {
        catenarySections::fillEnds(line, s);
        return;
    }
    const double w = line.weight, L = line.length;
    if (s.regime == CatenaryRegime::touchdown) {
        s.groundedLength = std::clamp(L - s.V / w, 0.0, L);
        s.HA = std::max(s.H - line.seabedFriction * w * s.groundedLength, 0.0);
        s.VA = 0.0;
    } else {
        s.groundedLength = 0.0;
        s.HA = s.H;
        s.VA = s.V - w * L;
    }
}

std::string describe(double x, double z, double H, double V)
{
    return "horizontal span " + formatValue(x) + " m, vertical span "
        + formatValue(z) + " m, H = " + formatValue(H)
        + " N, V = " + formatValue(V) + " N";
}

CatenarySolution newton(const CatenaryLine& line, double x, double z,
                        CatenaryGuess start, const CatenaryOptions& options)
{
    const double scale = std::max(line.length, std::hypot(x, z));
    const double Hmin = 1e-200;
    double H = std::max(start.H, Hmin), V = start.V;
    Span f = span(line, H, V);
    double rx = f.x - x, rz = f.z - z, norm = std::hypot(rx, rz);
    int iteration = 0;
    while (!(norm <= options.tolerance * scale)) {
        if (iteration == options.maxIterations || !std::isfinite(norm)) {
            throw UndefinedStateError(
                "catenary: Newton did not converge in "
                + std::to_string(iteration) + " iterations (regime "
                + regimeName(grounded(line, V) ? CatenaryRegime::touchdown
                                               : CatenaryRegime::suspended)
                + ", residual " + formatValue(norm) + " m, "
                + describe(x, z, H, V) + ")");
        }
        ++iteration;
        const double det = f.xH * f.zV - f.xV * f.zH;
        const double dH = (-rx * f.zV + rz * f.xV) / det;
        const double dV = (-rz * f.xH + rx * f.zH) / det;
        double lambda = 1.0;
        for (int halving = 0;; ++halving) {
            const double Hn = std::max(H + lambda * dH, 0.1 * H);
            const double Vn = V + lambda * dV;
            const Span fn = span(line, std::max(Hn, Hmin), Vn);
            const double nn = std::hypot(fn.x - x, fn.z - z);
            if ((std::isfinite(nn) && nn <= (1.0 - 1e-4 * lambda) * norm)
                || halving == 30) {
                if (!std::isfinite(nn)) {
                    break; // leaves the iterate; reported above
                }
                H = std::max(Hn, Hmin);
                V = Vn;
                f = fn;
                rx = fn.x - x;
                rz = fn.z - z;
                norm = nn;
                break;
            }
            lambda *= 0.5;
        }
    }
    CatenarySolution s;
    s.regime = grounded(line, V) ? CatenaryRegime::touchdown
                                 : CatenaryRegime::suspended;
    s.H = H;
    s.V = V;
    s.iterations = iteration;
    s.residual = norm;
    fillEnds(line, s);
    return s;
}

} // namespace

double totalLength(const CatenaryLine& line)
{
    double L = line.length;
    for (const CatenarySection& s : line.sections) {
        L += s.length;
    }
    return L;
}

double totalWeight(const CatenaryLine& line)
{
    double W = line.weight * line.length;
    for (const CatenarySection& s : line.sections) {
        W += s.jointWeight + s.weight * s.length;
    }
    return W;
}

const char* regimeName(CatenaryRegime regime)
{
    // in the order of the enumeration
    static const char* const names[]
        = {"suspended", "touchdown", "slackOnSeabed",
           "vertical",  "folded",    "slackWeightless"};
    static_assert(std::size(names)
                  == std::size_t(CatenaryRegime::slackWeightless) + 1);
    const auto i = std::size_t(regime);
    return i < std::size(names) ? names[i] : "unknown";
}

CatenarySolution solveCatenary(const CatenaryLine& line, double x, double z,
                               const CatenaryGuess* guess,
                               const CatenaryOptions& options)
{
    const double L = line.length, EA = line.EA, w = line.weight;
    const double tiny = 1e-12 * L;
    CatenarySolution s;
    if (line.seabedContact) {
        if (z < -tiny) {
            throw UndefinedStateError("catenary: the fairlead is "
                                      + formatValue(-z)
                                      + " m below the seabed (the anchor's "
                                        "height): "
                                      + describe(x, z, 0, 0));
        }
        z = std::max(z, 0.0);
    }
    if (!line.sections.empty()) {
        if (catenarySections::closedForm(line, x, z, s)) {
            return s;
        }
        return newton(line, x, z, start(guess, line, x, z), options);
    }
    if (w == 0.0 && std::hypot(x, z) <= L) {
        s.regime = CatenaryRegime::slackWeightless;
        return s;
    }
    if (line.seabedContact && w > 0.0) {
        const double Ls = verticalHangLength(line, z);
        if (Ls < L && x <= L - Ls) {
            s.regime = CatenaryRegime::slackOnSeabed;
            s.V = w * Ls;
            s.groundedLength = L - Ls;
            return s;
        }
    }
    if (x <= tiny) {
        // H = 0, both ends on one vertical. Taut: z = +-L + (V L - w L^2/2)/EA.
        // Slack: the line folds (one strand up, one down, T = 0 at the fold):
        // the H -> 0 limit of the suspended relation, 2V - wL = z/(1/|w| + L/(2EA))
        const double sign = z > 0.0 ? 1.0 : -1.0;
        s.regime = CatenaryRegime::vertical;
        s.V = (z - sign * L) * EA / L + 0.5 * w * L;
        s.VA = s.V - w * L;
        if (z != 0.0 && std::min(sign * s.V, sign * s.VA) >= 0.0) {
            return s;
        }
        s.regime = CatenaryRegime::folded;
        s.V = 0.5 * (w * L + z / (1.0 / std::abs(w) + L / (2.0 * EA)));
        s.VA = s.V - w * L;
        return s;
    }
    return newton(line, x, z, start(guess, line, x, z), options);
}

Eigen::Vector2d catenaryPoint(const CatenaryLine& line,
                              const CatenarySolution& sol, double x, double z,
                              double s)
{
    if (!line.sections.empty()) {
        return catenarySections::point(line, sol, x, z, s);
    }
    const double L = line.length, EA = line.EA, w = line.weight, H = sol.H;
    s = std::clamp(s, 0.0, L);
    switch (sol.regime) {
    case CatenaryRegime::slackWeightless:
        return Eigen::Vector2d(x, z) * (s / L);
    case CatenaryRegime::vertical:
    case CatenaryRegime::folded: {
        // H -> 0 limit of the suspended relation: each strand straight up
        // or down, the fold where the vertical tension changes sign
        const double Vs = sol.VA + w * s;
        const double across = std::abs(Vs) + std::abs(sol.VA);
        const double ratio = across > 0.0 ? (2.0 * sol.VA + w * s) / across
                                          : (z >= 0.0 ? 1.0 : -1.0);
        return {0.0, s * ratio + (sol.VA * s + 0.5 * w * s * s) / EA};
    }
    case CatenaryRegime::suspended: {
        const Span f = suspendedSpan(s, EA, w, H, sol.VA);
        return {s == 0.0 ? 0.0 : f.x, s == 0.0 ? 0.0 : f.z};
    }
    case CatenaryRegime::touchdown:
    case CatenaryRegime::slackOnSeabed:
        break;
    }
    const double Lb = sol.groundedLength;
    const bool heap = sol.regime == CatenaryRegime::slackOnSeabed;
    const double sg = std::min(s, Lb);
    double xg = heap ? std::min(sg, x) : sg + H * sg / EA;
    const double CB = line.seabedFriction;
    if (!heap && CB > 0.0) {
        const double c = CB * w, s0 = std::max(Lb - H / c, 0.0);
        xg = sg
            + (sg <= s0
                   ? 0.0
                   : (H * (sg - s0)
                      - 0.5 * c
                          * ((Lb - s0) * (Lb - s0) - (Lb - sg) * (Lb - sg)))
                       / EA);
    }
    if (s <= Lb) {
        return {xg, 0.0};
    }
    const double sl = s - Lb;
    if (heap) {
        return {x, sl + 0.5 * w * sl * sl / EA};
    }
    const double a = w * sl / H;
    return {xg + sl * asinhOverX(a) + H * sl / EA,
            sl * a / (std::hypot(1.0, a) + 1.0) + 0.5 * w * sl * sl / EA};
}

double catenaryTension(const CatenaryLine& line, const CatenarySolution& sol,
                       double s)
{
    if (!line.sections.empty()) {
        return catenarySections::tension(line, sol, s);
    }
    const double w = line.weight, H = sol.H;
    s = std::clamp(s, 0.0, line.length);
    switch (sol.regime) {
    case CatenaryRegime::slackWeightless:
        return 0.0;
    case CatenaryRegime::vertical:
    case CatenaryRegime::folded:
    case CatenaryRegime::suspended:
        return std::hypot(H, sol.VA + w * s);
    case CatenaryRegime::touchdown:
    case CatenaryRegime::slackOnSeabed:
        break;
    }
    const double Lb = sol.groundedLength;
    if (s > Lb) {
        return std::hypot(H, w * (s - Lb));
    }
    // on the seabed: the friction takes CB w per m from H towards the anchor
    return std::max(H - line.seabedFriction * w * (Lb - s), 0.0);
}

double catenaryEnergy(const CatenaryLine& line, const CatenarySolution& sol,
                      double x, double z)
{
    if (!line.sections.empty()) {
        return catenarySections::energy(line, sol, x);
    }
    const double L = line.length, EA = line.EA, w = line.weight, H = sol.H;
    if (sol.regime == CatenaryRegime::slackWeightless) {
        return 0.0;
    }
    const double Lb = sol.groundedLength, Ls = L - Lb;
    // Suspended part: T^2 = H^2 + (VA' + w s)^2, VA' the vertical tension
    // at its lower end (0 at the touchdown point)
    const double Va = Lb > 0.0 ? 0.0 : sol.VA, V = sol.V;
    double strain = H * H * Ls + Ls * (Va * Va + Va * V + V * V) / 3.0;
    if (Lb > 0.0 && sol.regime == CatenaryRegime::touchdown) {
        // Grounded part: T rises linearly to H at the touchdown point
        const double c = line.seabedFriction * w;
        const double s0 = c > 0.0 ? std::max(Lb - H / c, 0.0) : 0.0;
        const double T0 = c > 0.0 ? H - c * (Lb - s0) : H;
        strain += (Lb - s0) * (T0 * T0 + T0 * H + H * H) / 3.0;
    }
    strain /= 2.0 * EA;
    // Weight: w times the integral of z over the suspended part (z(s) is
    // analytic there; a folded line is integrated on each side of its fold)
    const auto integrateZ = [&](double from, double to) {
        return catenarySpan::integrate(
            [&](double s) { return catenaryPoint(line, sol, x, z, s)[1]; },
            from, to);
    };
    const double fold = sol.regime == CatenaryRegime::folded
        ? std::clamp(-sol.VA / w, Lb, L)
        : L;
    const double zIntegral = integrateZ(Lb, fold) + integrateZ(fold, L);
    return strain + w * zIntegral;
}

CatenarySectionTensions catenarySectionTensions(const CatenaryLine& line,
                                                const CatenarySolution& sol,
                                                double x)
{
    if (!line.sections.empty()) {
        return catenarySections::sectionTensions(line, sol, x);
    }
    CatenarySectionTensions t;
    t.lower = {catenaryTension(line, sol, 0.0)};
    t.upper = {catenaryTension(line, sol, line.length)};
    return t;
}

} // namespace connectors
