// The connector interface's vocabulary (fmuImport::connector): the terms
// and their rules, and a connector FMU's variables resolved against them,
// as fmusim check and the OpenFOAM bridge both use them.
#include "zipFixtures.hpp"

#include "fmuImport/fmuImport.hpp"

#include <gtest/gtest.h>

#include <algorithm>

namespace {

using fixtures::fmuPath;
using fmuImport::connector::Problem;
using fmuImport::connector::Variables;

const fmuImport::connector::Term& term(const std::string& base)
{
    for (const fmuImport::connector::Term& t :
         fmuImport::connector::vocabulary())
        if (t.base == base)
            return t;
    throw std::runtime_error("no term " + base);
}

TEST(ConnectorVocabulary, TermsAndRules)
{
    using fmuImport::connector::Requirement;
    EXPECT_EQ(term("A.r").requirement, Requirement::always);
    EXPECT_EQ(term("B.M").requirement, Requirement::twoBody);
    EXPECT_EQ(term("A.p").causality, fmuImport::Causality::parameter);
    EXPECT_EQ(term("A.p").variability, fmuImport::Variability::fixed);
    EXPECT_EQ(term("tension").units, std::vector<std::string>({"N"}));
    // A rotation matrix has no other unit: none declared is accepted
    EXPECT_EQ(term("A.R").units, std::vector<std::string>({"1", ""}));
    EXPECT_EQ(fmuImport::connector::componentNames(
                  "A.J", fmuImport::connector::Shape::matrix)[5],
              "A.J[2,3]");
}

TEST(ConnectorVocabulary, TestSpringFollowsTheInterface)
{
    fixtures::PrivateTmpDir tmp;
    const fmuImport::Fmu fmu(fmuPath("testSpring"));
    const Variables variables(fmu);
    EXPECT_TRUE(variables.twoBody());
    EXPECT_TRUE(variables.problems().empty())
        << variables.problems().front().text;
    EXPECT_TRUE(variables.missingRequired().empty());
    EXPECT_EQ(variables.refs("A.R"),
              std::vector<unsigned int>({3, 4, 5, 6, 7, 8, 9, 10, 11}));
    EXPECT_EQ(variables.refs("B.F"), std::vector<unsigned int>({38, 39, 40}));
    EXPECT_FALSE(variables.declared("A.v"));
    EXPECT_FALSE(variables.declared("stiffness")); // not a term
}

TEST(ConnectorVocabulary, WrongUnitIsAProblem)
{
    fixtures::PrivateTmpDir tmp;
    const fmuImport::Fmu fmu(fmuPath("testSpringUnbalanced"));
    const Variables variables(fmu);
    ASSERT_FALSE(variables.problems().empty());
    const Problem& p = variables.problems().front();
    EXPECT_EQ(p.kind, Problem::Kind::unit);
    EXPECT_EQ(p.variable, "A.F[1]");
    EXPECT_EQ(p.text, "A.F[1] has unit 'kN', expected 'N'");
    // Declared all the same: the loads can be read
    EXPECT_TRUE(variables.declared("A.F"));
}

TEST(ConnectorVocabulary, NonConnectorMissesTheRequiredTerms)
{
    fixtures::PrivateTmpDir tmp;
    const fmuImport::Fmu fmu(fmuPath("firstOrderLag"));
    const Variables variables(fmu);
    EXPECT_FALSE(variables.twoBody());
    EXPECT_EQ(variables.missingRequired(),
              std::vector<std::string>({"A.r", "A.R", "A.F", "A.M"}));
    ASSERT_FALSE(variables.problems().empty());
    EXPECT_EQ(variables.problems().front().text, "missing A.r[1]");
    EXPECT_TRUE(variables.problems().front().required);
}

} // namespace
