// Fixture for tests that run on every connector FMU built by the project
// (the list comes from CMake: FOAMFMI_CONNECTOR_FMUS, comma separated).
#ifndef TESTS_FMU_CONNECTORFMUTEST_HPP
#define TESTS_FMU_CONNECTORFMUTEST_HPP

#include <gtest/gtest.h>

#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "FmuHarness.hpp"

namespace fmuTest {

inline std::vector<std::string> connectorFmuNames()
{
    std::vector<std::string> names;
    std::istringstream list(FOAMFMI_CONNECTOR_FMUS);
    for (std::string name; std::getline(list, name, ',');) {
        names.push_back(name);
    }
    return names;
}

class ConnectorFmu : public ::testing::TestWithParam<std::string> {
protected:
    void SetUp() override { fmu = std::make_unique<LoadedFmu>(GetParam()); }

    std::unique_ptr<LoadedFmu> fmu;
};

} // namespace fmuTest

#define FMU_TEST_INSTANTIATE(suite)                                            \
    INSTANTIATE_TEST_SUITE_P(                                                  \
        Connectors, suite, ::testing::ValuesIn(fmuTest::connectorFmuNames()),  \
        [](const ::testing::TestParamInfo<std::string>& info) {                \
            return info.param;                                                 \
        })

#endif
