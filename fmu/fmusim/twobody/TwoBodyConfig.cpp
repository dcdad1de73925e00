#include "twobody/TwoBodyConfig.hpp"

#include "io/Args.hpp"
#include "Errors.hpp"

#include <sstream>
#include <utility>

namespace fmusim {

namespace {

[[noreturn]] void reject(const Setting& s, const std::string& problem)
{
    const std::string message = s.origin + ": " + s.name + ": " + problem;
    if (s.fromFile)
        throw FileError(message);
    throw UsageError(message);
}

// Numbers separated by blanks or commas.
std::vector<double> numbers(const Setting& s)
{
    std::string text = s.value;
    for (char& c : text)
        if (c == ',')
            c = ' ';
    std::istringstream in(text);
    std::vector<double> values;
    std::string word;
    while (in >> word) {
        const std::optional<double> value = toNumber(word);
        if (!value)
            reject(s, "'" + word + "' is not a finite number");
        values.push_back(*value);
    }
    return values;
}

double scalar(const Setting& s)
{
    const std::vector<double> v = numbers(s);
    if (v.size() != 1)
        reject(s, "expected one number, found '" + s.value + "'");
    return v[0];
}

Eigen::Vector3d vector(const Setting& s)
{
    const std::vector<double> v = numbers(s);
    if (v.size() != 3)
        reject(s, "expected three numbers, found '" + s.value + "'");
    return Eigen::Vector3d(v[0], v[1], v[2]);
}

Eigen::Matrix3d inertia(const Setting& s)
{
    const std::vector<double> v = numbers(s);
    Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
    if (v.size() == 3)
        J.diagonal() << v[0], v[1], v[2];
    else if (v.size() == 6)
        J << v[0], v[3], v[4], v[3], v[1], v[5], v[4], v[5], v[2];
    else if (v.size() == 9)
        J << v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8];
    else
        reject(s, "expected 3 (Jxx Jyy Jzz), 6 (and Jxy Jxz Jyz) or 9 numbers");
    if ((J - J.transpose()).norm() > 1e-12 * J.norm())
        reject(s, "the inertia tensor is not symmetric");
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(J);
    if (eigen.eigenvalues().minCoeff() <= 0)
        reject(s, "the inertia tensor is not positive definite");
    return J;
}

void applyBody(Body& body, const std::string& key, const Setting& s)
{
    if (key == "motion") {
        if (s.value == "free")
            body.motion = MotionKind::free;
        else if (s.value == "fixed")
            body.motion = MotionKind::fixed;
        else if (s.value == "sinusoidal")
            body.motion = MotionKind::sinusoidal;
        else if (s.value == "world")
            body.motion = MotionKind::world;
        else
            reject(s,
                   "'" + s.value + "' is not free, fixed, sinusoidal or world");
    } else if (key == "mass") {
        body.mass = scalar(s);
        if (!(body.mass > 0))
            reject(s, "the mass must be positive");
    } else if (key == "inertia")
        body.inertia = inertia(s);
    else if (key == "position")
        body.initial.x = vector(s);
    else if (key == "velocity")
        body.initial.v = vector(s);
    else if (key == "angular-velocity")
        body.initial.omega = vector(s);
    else if (key == "orientation") {
        const std::vector<double> q = numbers(s);
        if (q.size() != 4)
            reject(s, "expected a quaternion w x y z");
        const Eigen::Quaterniond quaternion(q[0], q[1], q[2], q[3]);
        if (quaternion.norm() < 1e-12)
            reject(s, "the quaternion is zero");
        body.initial.q = quaternion.normalized();
    } else if (key == "amplitude")
        body.amplitude = vector(s);
    else if (key == "rotation-amplitude")
        body.rotationAmplitude = vector(s);
    else if (key == "frequency")
        body.frequency = scalar(s);
    else if (key == "phase")
        body.phase = scalar(s);
}

// The keys of one number, and of one number taken as a count
const std::pair<const char*, double TwoBodyConfig::*> numberKeys[] = {
    {"start-time", &TwoBodyConfig::startTime},
    {"stop-time", &TwoBodyConfig::stopTime},
    {"step-size", &TwoBodyConfig::stepSize},
    {"coupling-tolerance", &TwoBodyConfig::couplingTolerance},
    {"initial-relaxation", &TwoBodyConfig::initialRelaxation},
    {"timeout", &TwoBodyConfig::timeout},
};
const std::pair<const char*, int TwoBodyConfig::*> countKeys[] = {
    {"write-every", &TwoBodyConfig::writeEvery},
    {"max-coupling-iterations", &TwoBodyConfig::maxCouplingIterations},
};

void apply(TwoBodyConfig& c, const Setting& s)
{
    const std::string& key = s.name;
    if (key.size() > 2 && (key[0] == 'A' || key[0] == 'B') && key[1] == '.') {
        applyBody(key[0] == 'A' ? c.A : c.B, key.substr(2), s);
        if (key == "B.motion")
            c.bMotionGiven = true;
        return;
    }
    for (const auto& [name, member] : numberKeys) {
        if (key == name) {
            c.*member = scalar(s);
            return;
        }
    }
    for (const auto& [name, member] : countKeys) {
        if (key == name) {
            c.*member = static_cast<int>(scalar(s));
            return;
        }
    }
    if (key == "gravity")
        c.gravity = vector(s);
    else if (key == "output-file")
        c.outputFile = s.value;
    else if (key == "isolation") {
        const std::optional<fmuImport::Isolation> isolation
            = toIsolation(s.value);
        if (!isolation)
            reject(s, "'" + s.value + "' is not none or process");
        c.isolation = *isolation;
    } else if (key == "scheme") {
        if (s.value == "explicit")
            c.scheme = Scheme::explicitEuler;
        else if (s.value == "implicit")
            c.scheme = Scheme::implicitTrapezoidal;
        else
            reject(s, "'" + s.value + "' is not explicit or implicit");
    }
}

bool isKey(const std::string& name)
{
    for (const std::string& k : twoBodyKeys())
        if (k == name)
            return true;
    return false;
}

} // namespace

const std::vector<std::string>& twoBodyKeys()
{
    static const std::vector<std::string> keys = [] {
        std::vector<std::string> k {"start-time",
                                    "stop-time",
                                    "step-size",
                                    "scheme",
                                    "gravity",
                                    "output-file",
                                    "write-every",
                                    "coupling-tolerance",
                                    "max-coupling-iterations",
                                    "initial-relaxation",
                                    "timeout",
                                    "isolation"};
        for (const std::string body : {"A.", "B."})
            for (const char* key :
                 {"motion", "mass", "inertia", "position", "orientation",
                  "velocity", "angular-velocity", "amplitude",
                  "rotation-amplitude", "frequency", "phase"})
                k.push_back(body + key);
        return k;
    }();
    return keys;
}

TwoBodyConfig parseTwoBodyConfig(const std::vector<std::string>& arguments)
{
    std::set<std::string> valueOptions(twoBodyKeys().begin(),
                                       twoBodyKeys().end());
    valueOptions.insert({"config", "set", "parameters"});
    const Args args = parseArgs(arguments, valueOptions, {"logging"});
    if (args.positional.size() != 1)
        throw UsageError("twobody needs exactly one FMU file");

    TwoBodyConfig c;
    c.fmuPath = args.positional[0];
    c.logging = args.flag("logging");
    std::vector<Setting> settings;
    if (const auto file = args.last("config")) {
        settings = readSettingsFile(*file);
        for (const Setting& s : settings)
            if (!isKey(s.name))
                throw FileError(s.origin + ": unknown key '" + s.name + "'");
    }
    for (const auto& option : args.options) {
        if (!isKey(option.first))
            continue;
        for (const std::string& value : option.second)
            settings.push_back(
                {option.first, value, "--" + option.first, false});
    }
    for (const Setting& s : settings)
        apply(c, s);

    c.fmuSettings = fmuSettings(args);

    if (!(c.stepSize > 0))
        throw UsageError("step-size must be positive");
    if (!(c.stopTime > c.startTime))
        throw UsageError("stop-time must be after start-time");
    if (c.writeEvery < 1)
        throw UsageError("write-every must be at least 1");
    if (!(c.couplingTolerance > 0))
        throw UsageError("coupling-tolerance must be positive");
    if (c.maxCouplingIterations < 1)
        throw UsageError("max-coupling-iterations must be at least 1");
    if (!(c.initialRelaxation > 0 && c.initialRelaxation <= 1))
        throw UsageError("initial-relaxation must be in (0, 1]");
    if (c.A.motion == MotionKind::world)
        throw UsageError("A.motion: only body B may be the world");
    if (!(c.timeout >= 0))
        throw UsageError("timeout must be a non-negative number of seconds");
    return c;
}

} // namespace fmusim
