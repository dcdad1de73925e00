#include "Connector.hpp"

namespace fmusim {

namespace {

void append(std::vector<unsigned int>& vrs, std::vector<double>& values,
            const std::vector<unsigned int>& blockVrs, const double* data,
            std::size_t n)
{
    vrs.insert(vrs.end(), blockVrs.begin(), blockVrs.end());
    values.insert(values.end(), data, data + n);
}

// Row-major copy of a matrix, matching the names R[1,1], R[1,2], ...
std::vector<double> rowMajor(const Eigen::Matrix3d& m)
{
    std::vector<double> out;
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            out.push_back(m(i, j));
    return out;
}

} // namespace

const std::vector<VocabularyEntry>& connectorVocabulary()
{
    using C = fmuImport::Causality;
    using V = fmuImport::Variability;
    static const std::vector<VocabularyEntry> vocabulary = [] {
        std::vector<VocabularyEntry> entries;
        for (const std::string body : {"A", "B"}) {
            const Requirement core
                = body == "A" ? Requirement::always : Requirement::twoBody;
            entries.push_back({body + ".r",
                               Shape::vector,
                               C::input,
                               V::continuous,
                               {"m"},
                               core});
            entries.push_back({body + ".R",
                               Shape::matrix,
                               C::input,
                               V::continuous,
                               {"1", ""},
                               core});
            entries.push_back({body + ".v",
                               Shape::vector,
                               C::input,
                               V::continuous,
                               {"m/s"},
                               Requirement::optional});
            entries.push_back({body + ".omega",
                               Shape::vector,
                               C::input,
                               V::continuous,
                               {"rad/s"},
                               Requirement::optional});
            entries.push_back({body + ".m",
                               Shape::scalar,
                               C::input,
                               V::continuous,
                               {"kg"},
                               Requirement::optional});
            entries.push_back({body + ".c",
                               Shape::vector,
                               C::input,
                               V::continuous,
                               {"m"},
                               Requirement::optional});
            entries.push_back({body + ".J",
                               Shape::matrix,
                               C::input,
                               V::continuous,
                               {"kg.m2"},
                               Requirement::optional});
            entries.push_back({body + ".F",
                               Shape::vector,
                               C::output,
                               V::continuous,
                               {"N"},
                               core});
            entries.push_back({body + ".M",
                               Shape::vector,
                               C::output,
                               V::continuous,
                               {"N.m"},
                               core});
            entries.push_back({body + ".p",
                               Shape::vector,
                               C::parameter,
                               V::fixed,
                               {"m"},
                               Requirement::optional});
        }
        entries.push_back({"length",
                           Shape::scalar,
                           C::output,
                           V::continuous,
                           {"m"},
                           Requirement::optional});
        entries.push_back({"lengthRate",
                           Shape::scalar,
                           C::output,
                           V::continuous,
                           {"m/s"},
                           Requirement::optional});
        entries.push_back({"tension",
                           Shape::scalar,
                           C::output,
                           V::continuous,
                           {"N"},
                           Requirement::optional});
        entries.push_back({"potentialEnergy",
                           Shape::scalar,
                           C::output,
                           V::continuous,
                           {"J"},
                           Requirement::optional});
        entries.push_back({"dissipatedPower",
                           Shape::scalar,
                           C::output,
                           V::continuous,
                           {"W"},
                           Requirement::optional});
        return entries;
    }();
    return vocabulary;
}

std::vector<std::string> componentNames(const std::string& base, Shape shape)
{
    std::vector<std::string> names;
    if (shape == Shape::scalar)
        return {base};
    for (int i = 1; i <= 3; ++i) {
        if (shape == Shape::vector) {
            names.push_back(base + "[" + std::to_string(i) + "]");
            continue;
        }
        for (int j = 1; j <= 3; ++j)
            names.push_back(base + "[" + std::to_string(i) + ","
                            + std::to_string(j) + "]");
    }
    return names;
}

Connector::Block Connector::find(const fmuImport::Fmu& fmu,
                                 const std::string& base, Shape shape)
{
    Block b;
    b.names = componentNames(base, shape);
    b.declared = true;
    for (const std::string& name : b.names) {
        if (!fmu.hasVariable(name)
            || fmu.variable(name).type != fmuImport::Type::Real) {
            b.declared = false;
            b.vrs.clear();
            return b;
        }
        b.vrs.push_back(fmu.variable(name).valueReference);
    }
    return b;
}

Connector::Body Connector::findBody(const fmuImport::Fmu& fmu,
                                    const std::string& prefix)
{
    Body b;
    b.r = find(fmu, prefix + ".r", Shape::vector);
    b.R = find(fmu, prefix + ".R", Shape::matrix);
    b.v = find(fmu, prefix + ".v", Shape::vector);
    b.omega = find(fmu, prefix + ".omega", Shape::vector);
    b.m = find(fmu, prefix + ".m", Shape::scalar);
    b.c = find(fmu, prefix + ".c", Shape::vector);
    b.J = find(fmu, prefix + ".J", Shape::matrix);
    b.F = find(fmu, prefix + ".F", Shape::vector);
    b.M = find(fmu, prefix + ".M", Shape::vector);
    return b;
}

Connector::Connector(const fmuImport::Fmu& fmu)
    : A_(findBody(fmu, "A")), B_(findBody(fmu, "B"))
{
    for (const fmuImport::Variable& v : fmu.modelDescription().variables)
        if (v.causality == fmuImport::Causality::input
            && v.name.compare(0, 2, "B.") == 0)
            twoBody_ = true;
}

std::vector<std::string> Connector::missingRequired() const
{
    std::vector<std::string> missing;
    auto need = [&](const Block& b, const char* name) {
        if (!b.declared)
            missing.push_back(name);
    };
    need(A_.r, "A.r");
    need(A_.R, "A.R");
    need(A_.F, "A.F");
    need(A_.M, "A.M");
    if (twoBody_) {
        need(B_.r, "B.r");
        need(B_.R, "B.R");
        need(B_.F, "B.F");
        need(B_.M, "B.M");
    }
    return missing;
}

void Connector::setKinematics(WatchedInstance& instance, const Kinematics& A,
                              const Kinematics& B) const
{
    std::vector<unsigned int> vrs;
    std::vector<double> values;
    auto add = [&](const Body& body, const Kinematics& k) {
        if (body.r.declared)
            append(vrs, values, body.r.vrs, k.r.data(), 3);
        if (body.R.declared)
            append(vrs, values, body.R.vrs, rowMajor(k.R).data(), 9);
        if (body.v.declared)
            append(vrs, values, body.v.vrs, k.v.data(), 3);
        if (body.omega.declared)
            append(vrs, values, body.omega.vrs, k.omega.data(), 3);
    };
    add(A_, A);
    if (twoBody_)
        add(B_, B);
    instance.setReal(vrs, values);
}

void Connector::setMassProperties(WatchedInstance& instance,
                                  const MassProperties& A,
                                  const MassProperties& B) const
{
    std::vector<unsigned int> vrs;
    std::vector<double> values;
    auto add = [&](const Body& body, const MassProperties& p) {
        if (body.m.declared)
            append(vrs, values, body.m.vrs, &p.m, 1);
        if (body.c.declared)
            append(vrs, values, body.c.vrs, p.c.data(), 3);
        if (body.J.declared)
            append(vrs, values, body.J.vrs, rowMajor(p.J).data(), 9);
    };
    add(A_, A);
    if (twoBody_)
        add(B_, B);
    if (!vrs.empty())
        instance.setReal(vrs, values);
}

void Connector::getLoads(WatchedInstance& instance, Loads& A, Loads& B) const
{
    std::vector<unsigned int> vrs = A_.F.vrs;
    vrs.insert(vrs.end(), A_.M.vrs.begin(), A_.M.vrs.end());
    if (hasLoadsB()) {
        vrs.insert(vrs.end(), B_.F.vrs.begin(), B_.F.vrs.end());
        vrs.insert(vrs.end(), B_.M.vrs.begin(), B_.M.vrs.end());
    }
    const std::vector<double> values = instance.getReal(vrs);
    A.F = Eigen::Vector3d(values[0], values[1], values[2]);
    A.M = Eigen::Vector3d(values[3], values[4], values[5]);
    if (hasLoadsB()) {
        B.F = Eigen::Vector3d(values[6], values[7], values[8]);
        B.M = Eigen::Vector3d(values[9], values[10], values[11]);
    } else {
        B = Loads();
    }
}

std::vector<std::pair<std::string, unsigned int>>
Connector::kinematicInputs() const
{
    std::vector<std::pair<std::string, unsigned int>> inputs;
    for (const Body* body : {&A_, &B_}) {
        if (body == &B_ && !twoBody_)
            break;
        for (const Block* b : {&body->r, &body->R, &body->v, &body->omega})
            for (std::size_t i = 0; i < b->vrs.size(); ++i)
                inputs.emplace_back(b->names[i], b->vrs[i]);
    }
    return inputs;
}

} // namespace fmusim
