// The FMI 3.0 get and set calls of LocalInstance: each value of the
// importer's types to and from the FMU's element types, by element
// (ElementPlan.hpp): whole arrays, one call per element type. The integer
// types go through long double, Binary as hexadecimal text.
#include "LocalInstance.hpp"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>

namespace fmuImport {

namespace {

std::string hexText(const fmi3Byte* bytes, std::size_t size)
{
    static const char* const digits = "0123456789abcdef";
    std::string text;
    for (std::size_t i = 0; i < size; ++i) {
        text += digits[bytes[i] >> 4];
        text += digits[bytes[i] & 15];
    }
    return text;
}

int hexDigit(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    return -1;
}

// The values of a set: every element of the plan's arrays, those not set
// as read (read(group, buffer)) when the set covers only part of them
template <class T, class Read>
std::vector<std::vector<T>> toSet(const ElementPlan& p,
                                  const std::vector<T>& values, Read read)
{
    std::vector<std::vector<T>> buffers(p.groups.size());
    for (std::size_t g = 0; g < p.groups.size(); ++g) {
        if (p.complete)
            buffers[g].resize(p.groups[g].count);
        else
            read(p.groups[g], buffers[g]);
    }
    for (std::size_t k = 0; k < values.size(); ++k)
        buffers[p.where[k].first][p.where[k].second] = values[k];
    return buffers;
}

// The values asked for, from the groups' values
template <class T>
std::vector<T> asked(const ElementPlan& p,
                     const std::vector<std::vector<T>>& buffers)
{
    std::vector<T> values(p.where.size());
    for (std::size_t k = 0; k < values.size(); ++k)
        values[k] = buffers[p.where[k].first][p.where[k].second];
    return values;
}

} // namespace

void LocalInstance::getReal3(const std::vector<unsigned int>& vrs,
                             double* values)
{
    const ElementPlan& p = plan(vrs, Type::Real, "fmi3GetFloat64");
    if (p.direct && p.groups[0].typeName == "Float64") {
        const ElementPlan::Group& g = p.groups[0];
        check(call("fmi3GetFloat64", time, api3().GetFloat64, component_,
                   g.refs.data(), g.refs.size(), values, g.count),
              "fmi3GetFloat64", time);
        return;
    }
    std::vector<std::vector<double>> buffers;
    for (const ElementPlan::Group& g : p.groups) {
        buffers.emplace_back(g.count);
        if (g.typeName == "Float64") {
            check(call("fmi3GetFloat64", time, api3().GetFloat64, component_,
                       g.refs.data(), g.refs.size(), buffers.back().data(),
                       g.count),
                  "fmi3GetFloat64", time);
            continue;
        }
        std::vector<float> raw(g.count);
        check(call("fmi3GetFloat32", time, api3().GetFloat32, component_,
                   g.refs.data(), g.refs.size(), raw.data(), g.count),
              "fmi3GetFloat32", time);
        buffers.back().assign(raw.begin(), raw.end());
    }
    const std::vector<double> got = asked(p, buffers);
    std::copy(got.begin(), got.end(), values);
}

void LocalInstance::setReal3(const std::vector<unsigned int>& vrs,
                             const std::vector<double>& values)
{
    const ElementPlan& p = plan(vrs, Type::Real, "fmi3SetFloat64");
    if (p.direct && p.groups[0].typeName == "Float64") {
        const ElementPlan::Group& g = p.groups[0];
        check(call("fmi3SetFloat64", time, api3().SetFloat64, component_,
                   g.refs.data(), g.refs.size(), values.data(), g.count),
              "fmi3SetFloat64", time);
        return;
    }
    // Part of an array: the others keep their values, which the FMU tells
    // from initialization mode on; before it (fmi3Get is not allowed when
    // instantiated) they are those set last, or the start values
    std::vector<std::vector<double>> buffers(p.groups.size());
    for (std::size_t g = 0; g < p.groups.size(); ++g) {
        const ElementPlan::Group& group = p.groups[g];
        buffers[g].resize(group.count);
        if (p.complete)
            continue;
        if (!initializing_) {
            std::size_t at = 0;
            for (const unsigned int array : group.refs) {
                const auto known = setBeforeInitialization_.find(array);
                for (const std::size_t i : fmu->elementsOf.at(array)) {
                    const Variable& e = fmu->description.variables[i];
                    buffers[g][at] = known != setBeforeInitialization_.end()
                        ? known->second[e.element]
                        : e.start;
                    ++at;
                }
            }
        } else if (group.typeName == "Float64") {
            check(call("fmi3GetFloat64", time, api3().GetFloat64, component_,
                       group.refs.data(), group.refs.size(), buffers[g].data(),
                       group.count),
                  "fmi3GetFloat64", time);
        } else {
            std::vector<float> raw(group.count);
            check(call("fmi3GetFloat32", time, api3().GetFloat32, component_,
                       group.refs.data(), group.refs.size(), raw.data(),
                       group.count),
                  "fmi3GetFloat32", time);
            buffers[g].assign(raw.begin(), raw.end());
        }
    }
    for (std::size_t k = 0; k < vrs.size(); ++k)
        buffers[p.where[k].first][p.where[k].second] = values[k];
    for (std::size_t g = 0; g < p.groups.size(); ++g) {
        const ElementPlan::Group& group = p.groups[g];
        if (!initializing_) {
            std::size_t at = 0;
            for (const unsigned int array : group.refs) {
                const std::size_t n = fmu->elementsOf.at(array).size();
                setBeforeInitialization_[array].assign(
                    buffers[g].begin() + at, buffers[g].begin() + at + n);
                at += n;
            }
        }
        if (group.typeName == "Float64") {
            check(call("fmi3SetFloat64", time, api3().SetFloat64, component_,
                       group.refs.data(), group.refs.size(), buffers[g].data(),
                       group.count),
                  "fmi3SetFloat64", time);
            continue;
        }
        const std::vector<float> raw(buffers[g].begin(), buffers[g].end());
        check(call("fmi3SetFloat32", time, api3().SetFloat32, component_,
                   group.refs.data(), group.refs.size(), raw.data(),
                   group.count),
              "fmi3SetFloat32", time);
    }
}

// The integer types: each group read into, or written from, long double,
// which holds every value of every one of them exactly
#define FMUIMPORT_FMI3_INTEGERS(X)                                             \
    X(Int8, std::int8_t)                                                       \
    X(UInt8, std::uint8_t)                                                     \
    X(Int16, std::int16_t)                                                     \
    X(UInt16, std::uint16_t)                                                   \
    X(Int32, std::int32_t)                                                     \
    X(UInt32, std::uint32_t)                                                   \
    X(Int64, std::int64_t)                                                     \
    X(UInt64, std::uint64_t)

void LocalInstance::readIntegers(const ElementPlan::Group& g,
                                 std::vector<long double>& out)
{
    out.resize(g.count);
#define FMUIMPORT_READ(T, C)                                                   \
    if (g.typeName == #T) {                                                    \
        std::vector<C> raw(g.count);                                           \
        check(call("fmi3Get" #T, time, api3().Get##T, component_,              \
                   g.refs.data(), g.refs.size(), raw.data(), g.count),         \
              "fmi3Get" #T, time);                                             \
        out.assign(raw.begin(), raw.end());                                    \
        return;                                                                \
    }
    FMUIMPORT_FMI3_INTEGERS(FMUIMPORT_READ)
#undef FMUIMPORT_READ
}

void LocalInstance::writeIntegers(const ElementPlan::Group& g,
                                  const std::vector<long double>& in)
{
#define FMUIMPORT_WRITE(T, C)                                                  \
    if (g.typeName == #T) {                                                    \
        const std::vector<C> raw(in.begin(), in.end());                        \
        check(call("fmi3Set" #T, time, api3().Set##T, component_,              \
                   g.refs.data(), g.refs.size(), raw.data(), g.count),         \
              "fmi3Set" #T, time);                                             \
        return;                                                                \
    }
    FMUIMPORT_FMI3_INTEGERS(FMUIMPORT_WRITE)
#undef FMUIMPORT_WRITE
}

std::vector<int>
LocalInstance::getInteger3(const std::vector<unsigned int>& vrs)
{
    const ElementPlan& p = plan(vrs, Type::Integer, "fmi3GetInt32");
    std::vector<std::vector<long double>> buffers(p.groups.size());
    for (std::size_t g = 0; g < p.groups.size(); ++g)
        readIntegers(p.groups[g], buffers[g]);
    std::vector<int> values(vrs.size());
    for (std::size_t k = 0; k < vrs.size(); ++k) {
        const long double v = buffers[p.where[k].first][p.where[k].second];
        if (v < INT_MIN || v > INT_MAX)
            throw Error(
                "fmi3Get" + p.groups[p.where[k].first].typeName + " in FMU '"
                + fmuPath + "', instance '" + name + "': the value of '"
                + fmu->description.variables[fmu->byReference.at(vrs[k])].name
                + "' does not fit an int (" + std::to_string(v) + ")");
        values[k] = static_cast<int>(v);
    }
    return values;
}

void LocalInstance::setInteger3(const std::vector<unsigned int>& vrs,
                                const std::vector<int>& values)
{
    const ElementPlan& p = plan(vrs, Type::Integer, "fmi3SetInt32");
    const std::vector<std::vector<long double>> buffers = toSet(
        p, std::vector<long double>(values.begin(), values.end()),
        [this](const ElementPlan::Group& g, std::vector<long double>& out) {
            readIntegers(g, out);
        });
    for (std::size_t g = 0; g < p.groups.size(); ++g) {
        const std::string& t = p.groups[g].typeName;
        const bool isUnsigned = t[0] == 'U';
        const int bits = std::stoi(t.substr(isUnsigned ? 4 : 3));
        const long double lo = isUnsigned ? 0 : -std::ldexp(1.0L, bits - 1);
        const long double hi = std::ldexp(1.0L, isUnsigned ? bits : bits - 1);
        for (std::size_t k = 0; k < vrs.size(); ++k) {
            const long double v = buffers[g][p.where[k].second];
            if (p.where[k].first == g && (v < lo || v >= hi))
                throw Error(
                    "fmi3Set" + t + " in FMU '" + fmuPath + "', instance '"
                    + name + "': " + std::to_string(values[k]) + " for '"
                    + fmu->description.variables[fmu->byReference.at(vrs[k])]
                          .name
                    + "' is outside the range of " + t);
        }
        writeIntegers(p.groups[g], buffers[g]);
    }
}

std::vector<bool>
LocalInstance::getBoolean3(const std::vector<unsigned int>& vrs)
{
    const ElementPlan& p = plan(vrs, Type::Boolean, "fmi3GetBoolean");
    const ElementPlan::Group& g = p.groups.at(0); // one type: Boolean
    const std::unique_ptr<bool[]> raw(new bool[g.count]());
    check(call("fmi3GetBoolean", time, api3().GetBoolean, component_,
               g.refs.data(), g.refs.size(), raw.get(), g.count),
          "fmi3GetBoolean", time);
    std::vector<bool> values(vrs.size());
    for (std::size_t k = 0; k < vrs.size(); ++k)
        values[k] = raw[p.where[k].second];
    return values;
}

void LocalInstance::setBoolean3(const std::vector<unsigned int>& vrs,
                                const std::vector<bool>& values)
{
    const ElementPlan& p = plan(vrs, Type::Boolean, "fmi3SetBoolean");
    const ElementPlan::Group& g = p.groups.at(0);
    const std::unique_ptr<bool[]> raw(new bool[g.count]());
    if (!p.complete)
        check(call("fmi3GetBoolean", time, api3().GetBoolean, component_,
                   g.refs.data(), g.refs.size(), raw.get(), g.count),
              "fmi3GetBoolean", time);
    for (std::size_t k = 0; k < vrs.size(); ++k)
        raw[p.where[k].second] = values[k];
    check(call("fmi3SetBoolean", time, api3().SetBoolean, component_,
               g.refs.data(), g.refs.size(), raw.get(), g.count),
          "fmi3SetBoolean", time);
}

// String and Binary (as hexadecimal text)
void LocalInstance::readTexts(const ElementPlan::Group& g,
                              std::vector<std::string>& out)
{
    out.assign(g.count, std::string());
    if (g.typeName == "String") {
        std::vector<fmi3String> raw(g.count, nullptr);
        check(call("fmi3GetString", time, api3().GetString, component_,
                   g.refs.data(), g.refs.size(), raw.data(), g.count),
              "fmi3GetString", time);
        for (std::size_t i = 0; i < g.count; ++i)
            out[i] = raw[i] ? raw[i] : "";
        return;
    }
    std::vector<std::size_t> sizes(g.count, 0);
    std::vector<fmi3Binary> raw(g.count, nullptr);
    check(call("fmi3GetBinary", time, api3().GetBinary, component_,
               g.refs.data(), g.refs.size(), sizes.data(), raw.data(), g.count),
          "fmi3GetBinary", time);
    for (std::size_t i = 0; i < g.count; ++i)
        out[i] = raw[i] ? hexText(raw[i], sizes[i]) : "";
}

std::vector<std::string>
LocalInstance::getString3(const std::vector<unsigned int>& vrs)
{
    const ElementPlan& p = plan(vrs, Type::String, "fmi3GetString");
    std::vector<std::vector<std::string>> buffers(p.groups.size());
    for (std::size_t g = 0; g < p.groups.size(); ++g)
        readTexts(p.groups[g], buffers[g]);
    return asked(p, buffers);
}

void LocalInstance::setString3(const std::vector<unsigned int>& vrs,
                               const std::vector<std::string>& values)
{
    const ElementPlan& p = plan(vrs, Type::String, "fmi3SetString");
    const std::vector<std::vector<std::string>> buffers
        = toSet(p, values,
                [this](const ElementPlan::Group& g,
                       std::vector<std::string>& out) { readTexts(g, out); });
    for (std::size_t g = 0; g < p.groups.size(); ++g) {
        const ElementPlan::Group& group = p.groups[g];
        if (group.typeName == "String") {
            std::vector<fmi3String> raw;
            for (const std::string& s : buffers[g])
                raw.push_back(s.c_str());
            check(call("fmi3SetString", time, api3().SetString, component_,
                       group.refs.data(), group.refs.size(), raw.data(),
                       group.count),
                  "fmi3SetString", time);
            continue;
        }
        std::vector<std::vector<fmi3Byte>> bytes;
        for (const std::string& text : buffers[g]) {
            bytes.emplace_back();
            for (std::size_t i = 0; i + 1 < text.size(); i += 2) {
                const int hi = hexDigit(text[i]), lo = hexDigit(text[i + 1]);
                if (hi < 0 || lo < 0 || text.size() % 2)
                    throw Error("fmi3SetBinary in FMU '" + fmuPath
                                + "', instance '" + name + "': '" + text
                                + "' is not hexadecimal bytes");
                bytes.back().push_back(fmi3Byte(hi * 16 + lo));
            }
        }
        std::vector<std::size_t> sizes;
        std::vector<fmi3Binary> raw;
        for (const auto& b : bytes) {
            sizes.push_back(b.size());
            raw.push_back(b.data());
        }
        check(call("fmi3SetBinary", time, api3().SetBinary, component_,
                   group.refs.data(), group.refs.size(), sizes.data(),
                   raw.data(), group.count),
              "fmi3SetBinary", time);
    }
}

} // namespace fmuImport
