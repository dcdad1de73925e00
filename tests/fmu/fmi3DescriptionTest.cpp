// The FMI 3.0 modelDescription.xml and terminalsAndIcons.xml of every
// connector FMU: the rules the schema cannot express (unique names and
// value references, array dimensions against start values, every output
// in the ModelStructure and nothing else, dependencies on inputs and
// parameters, terminal members that exist) and the derivation from the
// FMI 2.0 table (every 2.0 scalar in exactly one 3.0 variable, names,
// value references and start values as docs/connector-fmu-interface.md
// says).
#include <map>
#include <set>
#include <sstream>

#include "ConnectorFmuTest.hpp"
#include "Fmi3Harness.hpp"

namespace {

using namespace fmuTest;

class Fmi3Description : public ConnectorFmu {
protected:
    void SetUp() override
    {
        ConnectorFmu::SetUp();
        fmu3 = std::make_unique<LoadedFmu3>(GetParam());
    }

    std::unique_ptr<LoadedFmu3> fmu3;
};

std::vector<fmi3ValueReference> references(const char* text)
{
    std::vector<fmi3ValueReference> out;
    std::istringstream in(text);
    for (fmi3ValueReference vr; in >> vr;) {
        out.push_back(vr);
    }
    return out;
}

TEST_P(Fmi3Description, NamesAndValueReferencesAreUnique)
{
    std::set<std::string> names;
    std::set<fmi3ValueReference> refs;
    for (const Variable3& v : fmu3->variables) {
        EXPECT_TRUE(names.insert(v.name).second) << v.name;
        EXPECT_TRUE(refs.insert(v.valueReference).second) << v.name;
    }
    EXPECT_FALSE(fmu3->variables.empty());
}

TEST_P(Fmi3Description, DimensionsMatchStartValues)
{
    for (const Variable3& v : fmu3->variables) {
        for (std::size_t d : v.dimensions) {
            EXPECT_GT(d, 0u) << v.name;
        }
        EXPECT_LE(v.dimensions.size(), 2u) << v.name;
        const pugi::xml_node node
            = fmu3->description.child("fmiModelDescription")
                  .child("ModelVariables")
                  .find_child_by_attribute("name", v.name.c_str());
        if (std::string(node.attribute("initial").value()) == "calculated") {
            // outputs and the continuous locals of line FMUs
            EXPECT_TRUE(v.causality == fmuImport::Causality::output
                        || v.causality == fmuImport::Causality::local)
                << v.name;
            EXPECT_TRUE(v.start.empty()) << v.name;
        } else {
            // One start value per element in the XML (the importer would
            // take one for all)
            std::istringstream start(node.attribute("start").value());
            std::size_t n = 0;
            for (std::string word; start >> word;) {
                ++n;
            }
            EXPECT_EQ(n, v.size) << v.name;
        }
    }
    EXPECT_EQ(fmu3->variable("A.r").dimensions, (std::vector<std::size_t> {3}));
    EXPECT_EQ(fmu3->variable("A.R").dimensions,
              (std::vector<std::size_t> {3, 3}));
    EXPECT_EQ(fmu3->variable("B.F").dimensions, (std::vector<std::size_t> {3}));
}

TEST_P(Fmi3Description, OutputsAreTheModelStructure)
{
    const pugi::xml_node structure
        = fmu3->description.child("fmiModelDescription")
              .child("ModelStructure");
    std::map<fmi3ValueReference, const Variable3*> byRef;
    std::set<fmi3ValueReference> outputs;
    for (const Variable3& v : fmu3->variables) {
        byRef[v.valueReference] = &v;
        if (v.causality == fmuImport::Causality::output) {
            outputs.insert(v.valueReference);
        }
    }
    for (const char* kind : {"Output", "InitialUnknown"}) {
        std::multiset<fmi3ValueReference> listed;
        for (const pugi::xml_node u : structure.children(kind)) {
            const fmi3ValueReference vr
                = u.attribute("valueReference").as_uint();
            listed.insert(vr);
            ASSERT_TRUE(u.attribute("dependencies")) << kind << " " << vr;
            for (fmi3ValueReference d :
                 references(u.attribute("dependencies").value())) {
                ASSERT_TRUE(byRef.count(d)) << kind << " " << vr << ": " << d;
                const fmuImport::Causality c = byRef[d]->causality;
                EXPECT_TRUE(c == fmuImport::Causality::input
                            || (c == fmuImport::Causality::parameter
                                && std::string(kind) == "InitialUnknown"))
                    << kind << " " << vr << " depends on " << byRef[d]->name;
            }
        }
        EXPECT_EQ(
            listed,
            std::multiset<fmi3ValueReference>(outputs.begin(), outputs.end()))
            << kind;
    }
    // Every child of ModelStructure is an Output or an InitialUnknown
    for (const pugi::xml_node u : structure.children()) {
        EXPECT_TRUE(std::string(u.name()) == "Output"
                    || std::string(u.name()) == "InitialUnknown")
            << u.name();
    }
}

TEST_P(Fmi3Description, DerivedFromTheFmi2Table)
{
    // The same instantiation token as the 2.0 GUID: one variable table
    EXPECT_EQ(fmu3->token, fmu->guid);
    std::map<std::string, const fmuImport::Variable*> scalars;
    for (const fmuImport::Variable& s : fmu->modelDescription().variables) {
        scalars.emplace(s.name, &s);
    }
    std::set<std::string> covered;
    for (const Variable3& v : fmu3->variables) {
        const std::vector<std::string> names = fmi2ElementNames(v);
        ASSERT_EQ(names.size(), v.size) << v.name;
        for (std::size_t i = 0; i < names.size(); ++i) {
            ASSERT_TRUE(scalars.count(names[i]))
                << v.name << " element " << i << ": no " << names[i];
            const fmuImport::Variable& s = *scalars.at(names[i]);
            EXPECT_TRUE(covered.insert(names[i]).second) << names[i];
            EXPECT_TRUE(s.causality == v.causality) << names[i];
            if (i == 0) {
                EXPECT_EQ(s.valueReference, v.valueReference) << v.name;
            }
            if (!v.start.empty()) {
                EXPECT_EQ(v.start[i], s.start) << names[i];
            }
        }
    }
    EXPECT_EQ(covered.size(), scalars.size());
}

TEST_P(Fmi3Description, TerminalsNameBodyVariables)
{
    const pugi::xml_node terminals
        = fmu3->terminals.child("fmiTerminalsAndIcons").child("Terminals");
    std::set<std::string> bodies;
    for (const pugi::xml_node t : terminals.children("Terminal")) {
        const std::string body = t.attribute("name").value();
        bodies.insert(body);
        std::set<std::string> members;
        for (const pugi::xml_node m : t.children("TerminalMemberVariable")) {
            const std::string name = m.attribute("variableName").value();
            EXPECT_NO_THROW(fmu3->variable(name)) << name;
            EXPECT_EQ(name, body + "." + m.attribute("memberName").value());
            members.insert(m.attribute("memberName").value());
        }
        for (const char* member : {"r", "R", "v", "omega", "F", "M", "p"}) {
            EXPECT_TRUE(members.count(member)) << body << "." << member;
        }
    }
    EXPECT_EQ(bodies, (std::set<std::string> {"A", "B"}));
}

FMU_TEST_INSTANTIATE(Fmi3Description);

} // namespace
