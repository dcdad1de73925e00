#include "io/ConnectorIo.hpp"

namespace fmusim {

namespace {

// A declared term's references and values (as many as it has components);
// nothing for an undeclared one.
void append(std::vector<unsigned int>& vrs, std::vector<double>& values,
            const std::vector<unsigned int>& termVrs, const double* data)
{
    vrs.insert(vrs.end(), termVrs.begin(), termVrs.end());
    values.insert(values.end(), data, data + termVrs.size());
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

ConnectorIo::ConnectorIo(const fmuImport::Fmu& fmu) : variables_(fmu)
{
}

void ConnectorIo::setKinematics(fmuImport::Instance& instance,
                                const Kinematics& A, const Kinematics& B) const
{
    std::vector<unsigned int> vrs;
    std::vector<double> values;
    auto add = [&](const std::string& body, const Kinematics& k) {
        append(vrs, values, variables_.refs(body + ".r"), k.r.data());
        append(vrs, values, variables_.refs(body + ".R"), rowMajor(k.R).data());
        append(vrs, values, variables_.refs(body + ".v"), k.v.data());
        append(vrs, values, variables_.refs(body + ".omega"), k.omega.data());
    };
    add("A", A);
    if (variables_.twoBody())
        add("B", B);
    instance.setReal(vrs, values);
}

void ConnectorIo::setMassProperties(fmuImport::Instance& instance,
                                    const MassProperties& A,
                                    const MassProperties& B) const
{
    std::vector<unsigned int> vrs;
    std::vector<double> values;
    auto add = [&](const std::string& body, const MassProperties& p) {
        append(vrs, values, variables_.refs(body + ".m"), &p.m);
        append(vrs, values, variables_.refs(body + ".c"), p.c.data());
        append(vrs, values, variables_.refs(body + ".J"), rowMajor(p.J).data());
    };
    add("A", A);
    if (variables_.twoBody())
        add("B", B);
    if (!vrs.empty())
        instance.setReal(vrs, values);
}

void ConnectorIo::getLoads(fmuImport::Instance& instance, Loads& A,
                           Loads& B) const
{
    std::vector<unsigned int> vrs;
    for (const char* term : {"A.F", "A.M", "B.F", "B.M"})
        if (term[0] == 'A' || hasLoadsB())
            for (const unsigned int vr : variables_.refs(term))
                vrs.push_back(vr);
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
ConnectorIo::kinematicInputs() const
{
    std::vector<std::pair<std::string, unsigned int>> inputs;
    using fmuImport::connector::Shape;
    for (const char* prefix : {"A", "B"}) {
        if (*prefix == 'B' && !variables_.twoBody())
            break;
        for (const auto& term : {std::make_pair(".r", Shape::vector),
                                 std::make_pair(".R", Shape::matrix),
                                 std::make_pair(".v", Shape::vector),
                                 std::make_pair(".omega", Shape::vector)}) {
            const std::string base = prefix + std::string(term.first);
            const std::vector<unsigned int>& vrs = variables_.refs(base);
            const std::vector<std::string> names
                = fmuImport::connector::componentNames(base, term.second);
            for (std::size_t i = 0; i < vrs.size(); ++i)
                inputs.emplace_back(names[i], vrs[i]);
        }
    }
    return inputs;
}

} // namespace fmusim
