// moordynDriver: MoorDyn v2 (its C API) on the two reference lines of
// mooringLineBench, with the same fairlead motion, for the comparison in
// bench/mooringLine/README.md. Built and run by ./run, outside the
// project's build (MoorDyn is not a dependency of the project).
//
// The fairlead (MoorDyn's coupled point) surges x0 + A r(t) sin(2 pi t/T),
// r = (1 - cos(pi t/T))/2 over the first period, then 1, as in
// mooringLineBench. MoorDyn moves a coupled point on a straight line from
// the position it is given at the start of a coupling step with the
// velocity it is given: the driver gives the position at t and the step's
// mean velocity (x(t + h) - x(t))/h, so the point passes through the
// bench's positions at every coupling instant. The fairlead tension is
// |f|, the force MoorDyn_Step returns on the coupled point (the line's end
// node: tension and its half segment's weight, buoyancy, drag and seabed
// forces, no inertia: mooringLine's loads with endInertia = 0). Measured:
// its first harmonic over the third period (rectangle rule at the coupling
// instants), and the CPU time of this thread and the wall time per
// simulated second over the stepping loop (MoorDyn_Init's start
// equilibrium not counted).
//
// Usage: moordynDriver lab|oc4 INPUT N dtM h [start] [mu=M] [fricDamp=C]
//        [surge=A | sway=A] [period=T] [vf=V]
//   INPUT: a MoorDyn input file of that line (lab.txt, oc4.txt here); its
//   line's NumSegs and the dtM option are replaced by N and dtM in a copy
//   written to a temporary directory, where MoorDyn also writes its output
//   file. `start`: give MoorDyn the fairlead's velocity at the start of
//   each coupling step instead of the step's mean velocity (the point then
//   ends the step at x(t) + h v(t), off the bench's path by about
//   h^2/2 times the acceleration).
//   mu=M, fricDamp=C: MoorDyn's seabed friction (the options
//   FrictionCoefficient and FricDamp [N s/m], written into the copy's
//   OPTIONS section; MoorDyn's defaults 0 and 200); surge=A, period=T: the
//   fairlead's surge amplitude [m] and period [s] (default the line's, as
//   mooringLineBench); sway=A: the same motion along y. mu= is for the
//   lab chain only: the driver then also prints, over the third period,
//   the tension's mean, its second harmonic and how the grounded free
//   nodes (below the seabed, z < the anchor's z) move, as
//   `mooringLineBench friction` does: their mean number, their largest
//   horizontal speed, the share of their node-steps faster than V
//   (default 0.01 m/s; MoorDyn's friction saturates above Fn/C, which is
//   V where C = Fn/V), and their push on the seabed (MoorDyn's:
//   kb (depth - z) d l - cb vz d l) over their submerged weight w l,
//   weighted by |v_h|^2 (mooringLineBench.cpp, frictionRow; d, l, w, kb,
//   cb of lab.txt).
#include <MoorDyn2.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

constexpr double pi = 3.14159265358979323846;

double cpuSeconds()
{
    timespec t {};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

//- The bench's fairlead motion (mooringLineBench.cpp, fairleadAt)
struct Motion {
    double x0, y0, z0, amplitude, period;
    //- 0: surge (along x), 1: sway (along y)
    int axis = 0;
    void at(double t, double x[3]) const
    {
        const double r
            = t < period ? 0.5 * (1.0 - std::cos(pi * t / period)) : 1.0;
        x[0] = x0;
        x[1] = y0;
        x[2] = z0;
        x[axis] += amplitude * r * std::sin(2.0 * pi * t / period);
    }
    void velocityAt(double t, double v[3]) const
    {
        const double w = 2.0 * pi / period;
        const double r
            = t < period ? 0.5 * (1.0 - std::cos(pi * t / period)) : 1.0;
        const double dr
            = t < period ? 0.5 * pi / period * std::sin(pi * t / period) : 0.0;
        v[0] = v[1] = v[2] = 0.0;
        v[axis] = amplitude * (dr * std::sin(w * t) + r * w * std::cos(w * t));
    }
};

//- The input file with the line's NumSegs (6th column of the row after
//  the LINES header's two rows) and the dtM option replaced, and `options`
//  (rows "value name") inserted after the OPTIONS header
std::string withSegmentsAndStep(const std::string& path, int N, double dtM,
                                const std::string& options = "")
{
    std::ifstream in(path);
    if (!in) {
        throw std::runtime_error("cannot read " + path);
    }
    std::ostringstream out;
    std::string line;
    int linesRow = -1; // rows since the LINES header
    bool segments = false, step = false;
    while (std::getline(in, line)) {
        std::istringstream words(line);
        std::vector<std::string> w;
        for (std::string s; words >> s;) {
            w.push_back(s);
        }
        if (line.find("LINES") != std::string::npos && line[0] == '-') {
            linesRow = 0;
        } else if (linesRow >= 0) {
            ++linesRow;
        }
        if (linesRow == 3) {
            if (w.size() < 7) {
                throw std::runtime_error(path + ": the line's row has "
                                         + std::to_string(w.size())
                                         + " entries, expected 7");
            }
            w[5] = std::to_string(N);
            line.clear();
            for (const std::string& s : w) {
                line += s + "  ";
            }
            segments = true;
            linesRow = -1;
        } else if (w.size() >= 2 && (w[1] == "dtM" || w[1] == "dtm")) {
            char value[32];
            std::snprintf(value, sizeof value, "%.17g", dtM);
            line = std::string(value) + "  dtM";
            step = true;
        }
        out << line << '\n';
        if (line.find("OPTIONS") != std::string::npos && line[0] == '-') {
            out << options;
        }
    }
    if (!segments || !step) {
        throw std::runtime_error(path + ": no "
                                 + (segments ? "dtM option" : "LINES row")
                                 + " to replace");
    }
    return out.str();
}

} // namespace

int main(int argc, char** argv)
{
    bool startVelocity = false, friction = false;
    int axis = 0;
    double mu = 0.0, fricDamp = 200.0, surge = -1.0, period = -1.0, vf = 0.01;
    for (int k = 6; k < argc; ++k) {
        const std::string a = argv[k];
        const std::size_t eq = a.find('=');
        const std::string key = a.substr(0, eq);
        const double value
            = eq == std::string::npos ? 0.0 : std::atof(a.c_str() + eq + 1);
        if (a == "start") {
            startVelocity = true;
        } else if (key == "mu" && eq != std::string::npos) {
            mu = value;
            friction = true;
        } else if (key == "fricDamp" && eq != std::string::npos) {
            fricDamp = value;
        } else if ((key == "surge" || key == "sway")
                   && eq != std::string::npos) {
            surge = value;
            axis = key == "sway" ? 1 : 0;
        } else if (key == "period" && eq != std::string::npos) {
            period = value;
        } else if (key == "vf" && eq != std::string::npos) {
            vf = value;
        } else {
            argc = 0; // usage
        }
    }
    if (argc >= 6 && friction && std::strcmp(argv[1], "lab") != 0) {
        std::fprintf(stderr, "moordynDriver: mu= is for the lab chain\n");
        return 2;
    }
    if (argc < 6) {
        std::fprintf(stderr,
                     "usage: %s lab|oc4 INPUT N dtM h [start] [mu=M] "
                     "[fricDamp=C] [surge=A | sway=A] [period=T] [vf=V]\n",
                     argv[0]);
        return 2;
    }
    const bool lab = std::strcmp(argv[1], "lab") == 0;
    if (!lab && std::strcmp(argv[1], "oc4") != 0) {
        std::fprintf(stderr, "moordynDriver: line %s: expected lab or oc4\n",
                     argv[1]);
        return 2;
    }
    Motion motion = lab ? Motion {0.0, 0.0, -0.05, 0.01, 1.0}
                        : Motion {-40.868, 0.0, -14.0, 1.0, 10.0};
    if (surge >= 0.0) {
        motion.amplitude = surge;
    }
    motion.axis = axis;
    if (period > 0.0) {
        motion.period = period;
    }
    const int N = std::atoi(argv[3]);
    const double dtM = std::atof(argv[4]), h = std::atof(argv[5]);
    if (N < 1 || !(dtM > 0.0) || !(h > 0.0)) {
        std::fprintf(stderr,
                     "moordynDriver: N = %s, dtM = %s, h = %s: "
                     "expected N >= 1, dtM > 0, h > 0\n",
                     argv[3], argv[4], argv[5]);
        return 2;
    }
    char directory[] = "/tmp/moordynDriverXXXXXX";
    if (!mkdtemp(directory)) {
        std::perror("moordynDriver: mkdtemp");
        return 1;
    }
    const std::string input = std::string(directory) + "/line.txt";
    try {
        char options[160] = "";
        if (friction) {
            std::snprintf(options, sizeof options,
                          "%.17g  FrictionCoefficient\n%.17g  FricDamp\n", mu,
                          fricDamp);
        }
        std::ofstream(input) << withSegmentsAndStep(argv[2], N, dtM, options);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "moordynDriver: %s\n", e.what());
        return 1;
    }
    MoorDyn system = MoorDyn_Create(input.c_str());
    unsigned int dofs = 0;
    if (!system || MoorDyn_NCoupledDOF(system, &dofs) != MOORDYN_SUCCESS
        || dofs != 3) {
        std::fprintf(stderr,
                     "moordynDriver: %s: expected one coupled point "
                     "(3 coupled DOFs)\n",
                     input.c_str());
        return 1;
    }
    MoorDyn_SetVerbosity(system, MOORDYN_ERR_LEVEL);
    double x[3], x1[3], v[3] = {0.0, 0.0, 0.0}, f[3];
    motion.at(0.0, x);
    if (MoorDyn_Init(system, x, v) != MOORDYN_SUCCESS) {
        std::fprintf(stderr, "moordynDriver: MoorDyn_Init failed\n");
        return 1;
    }
    // the start equilibrium's tension (a step of 0 returns the forces)
    double t0 = 0.0, zero = 0.0;
    if (MoorDyn_Step(system, x, v, f, &t0, &zero) != MOORDYN_SUCCESS) {
        std::fprintf(stderr, "moordynDriver: MoorDyn_Step failed at t = 0\n");
        return 1;
    }
    const double startTension
        = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
    const int perPeriod = int(std::lround(motion.period / h));
    std::complex<double> a1 = 0.0, a2 = 0.0;
    // the tension's mean and the grounded free nodes (mu=)
    double mean = 0.0, grounded = 0.0, fastest = 0.0, sliding = 0.0;
    double pushed = 0.0, squares = 0.0;
    const double d = 0.0036, l = 1.2 / N, kb = 3e5, cb = 3e3;
    const double wl = (0.0796 - 1025.0 * pi / 4.0 * d * d) * 9.81 * l;
    const double seabed = lab ? -0.5 : -200.0;
    MoorDynLine mooring = MoorDyn_GetLine(system, 1);
    const auto start = std::chrono::steady_clock::now();
    const double cpuStart = cpuSeconds();
    for (int k = 1; k <= 3 * perPeriod; ++k) {
        double t = (k - 1) * h, dt = h;
        motion.at(t, x);
        motion.at(k * h, x1);
        for (int d = 0; d < 3; ++d) {
            v[d] = (x1[d] - x[d]) / h;
        }
        if (startVelocity) {
            motion.velocityAt(t, v);
        }
        if (MoorDyn_Step(system, x, v, f, &t, &dt) != MOORDYN_SUCCESS) {
            std::fprintf(stderr,
                         "moordynDriver: MoorDyn_Step failed at "
                         "t = %g s\n",
                         (k - 1) * h);
            return 1;
        }
        const double T = std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
        if (k > 2 * perPeriod) {
            a1 += T
                * std::exp(std::complex<double>(
                    0.0, -2.0 * pi * k * h / motion.period));
            a2 += T
                * std::exp(std::complex<double>(
                    0.0, -4.0 * pi * k * h / motion.period));
            mean += T;
        }
        for (int i = 1; friction && k > 2 * perPeriod && i < N; ++i) {
            double r[3], u[3];
            if (MoorDyn_GetLineNodePos(mooring, i, r) != MOORDYN_SUCCESS
                || MoorDyn_GetLineNodeVel(mooring, i, u) != MOORDYN_SUCCESS) {
                std::fprintf(stderr, "moordynDriver: node %d: no state\n", i);
                return 1;
            }
            if (r[2] < seabed) {
                const double speed = std::hypot(u[0], u[1]);
                const double push = ((seabed - r[2]) * kb - u[2] * cb) * d * l;
                pushed += std::abs(push) / wl * speed * speed;
                squares += speed * speed;
                grounded += 1.0;
                fastest = std::max(fastest, speed);
                sliding += speed > vf ? 1.0 : 0.0;
            }
        }
    }
    const double cpu = (cpuSeconds() - cpuStart) / (3.0 * motion.period);
    const double wall = std::chrono::duration<double>(
                            std::chrono::steady_clock::now() - start)
                            .count()
        / (3.0 * motion.period);
    MoorDyn_Close(system);
    std::remove(input.c_str());
    std::remove((std::string(directory) + "/line.out").c_str());
    rmdir(directory);
    std::printf("MoorDyn %s N = %d dtM = %g h = %g%s: amplitude %.9g N, wall "
                "%.4g s (CPU %.4g s) per simulated s, start tension %.9g N\n",
                argv[1], N, dtM, h, startVelocity ? " (start velocity)" : "",
                2.0 * std::abs(a1) / perPeriod, wall, cpu, startTension);
    if (friction) {
        std::printf("MoorDyn friction N = %d dtM = %g mu = %g fricDamp = %g "
                    "%s %g m period %g s: mean %.9g N, amplitude %.9g N, "
                    "second %.9g N; grounded nodes %.3g, fastest %.3g m/s, "
                    "faster than %g m/s %.3g of node-steps, push %.3g w l\n",
                    N, dtM, mu, fricDamp, axis == 1 ? "sway" : "surge",
                    motion.amplitude, motion.period, mean / perPeriod,
                    2.0 * std::abs(a1) / perPeriod,
                    2.0 * std::abs(a2) / perPeriod, grounded / perPeriod,
                    fastest, vf, grounded > 0.0 ? sliding / grounded : 0.0,
                    squares > 0.0 ? pushed / squares : 0.0);
    }
    return 0;
}
