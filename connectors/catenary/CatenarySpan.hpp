// The closed-form pieces of the elastic catenary shared by the uniform line
// (CatenaryProfile.cpp) and the line of sections (CatenarySections.cpp):
// the span of a suspended piece and its derivatives, evaluated without
// 1/w cancellation. Internal to the catenary law.
#ifndef CONNECTORS_CATENARY_CATENARYSPAN_HPP
#define CONNECTORS_CATENARY_CATENARYSPAN_HPP

#include <cmath>

namespace connectors {
namespace catenarySpan {

//- asinh(d)/d, smooth through d = 0 (series error below 1e-25 there)
inline double asinhOverX(double d)
{
    return std::abs(d) < 1e-6 ? 1.0 - d * d / 6.0 : std::asinh(d) / d;
}

//- r = (a sb - b sa)/(a - b) with sa = sqrt(1+a^2), sb = sqrt(1+b^2),
//  without cancellation: asinh a - asinh b = asinh((a - b) r)
inline double divided(double a, double b, double sa, double sb)
{
    if (a * b > 0.0) {
        return (a + b) / (a * sb + b * sa);
    }
    if (a == b) {
        return 1.0; // a = b = 0
    }
    return (a * sb - b * sa) / (a - b);
}

//- Span (x, z) and its Jacobian d(x, z)/d(H, V) at one iterate
struct Span {
    double x = 0.0, z = 0.0;
    double xH = 0.0, xV = 0.0, zH = 0.0, zV = 0.0;
};

//- Suspended line of length s whose lower end carries vertical tension Va
//  and horizontal tension H > 0 (upper end: Va + w s); any sign of w. The
//  derivatives are at fixed s, V the upper end's vertical tension (Va
//  moving with it)
inline Span suspendedSpan(double s, double EA, double w, double H, double Va)
{
    const double V = Va + w * s;
    const double a = V / H, b = Va / H;
    const double sa = std::hypot(1.0, a), sb = std::hypot(1.0, b);
    const double r = divided(a, b, sa, sb);
    const double Q = r * asinhOverX(r * (a - b)); // (asinh a - asinh b)/(a-b)
    const double g = r / (sa * sb);
    const double p = -(a + b) / (sa * sb * (sa + sb));
    Span out;
    out.x = s * Q + H * s / EA;
    out.z = s * (a + b) / (sa + sb) + (Va * s + 0.5 * w * s * s) / EA;
    out.xH = (s / H) * (Q - g) + s / EA;
    out.xV = (s / H) * p;
    out.zH = (s / H) * p;
    out.zV = (s / H) * g + s / EA;
    return out;
}

//- Integral of f over [from, to]: composite 5-point Gauss-Legendre on 8
//  panels (for the heights along an analytic piece of the line)
template <class Function>
double integrate(const Function& f, double from, double to)
{
    static const double node[5] = {0.0, 0.5384693101056831, -0.5384693101056831,
                                   0.9061798459386640, -0.9061798459386640};
    static const double weightOf[5]
        = {0.5688888888888889, 0.4786286704993665, 0.4786286704993665,
           0.2369268850561891, 0.2369268850561891};
    const int panels = 8;
    const double h = (to - from) / panels;
    double sum = 0.0;
    for (int k = 0; k < panels; ++k) {
        const double mid = from + (k + 0.5) * h;
        for (int i = 0; i < 5; ++i) {
            sum += weightOf[i] * 0.5 * h * f(mid + 0.5 * h * node[i]);
        }
    }
    return sum;
}

} // namespace catenarySpan
} // namespace connectors

#endif
