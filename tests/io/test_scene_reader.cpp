// SPDX-License-Identifier: MIT
// Scene reader: overrides, unknown keys with hints, file:line in messages.
#include <gtest/gtest.h>

#include "io/scene_reader.hpp"

using namespace granulab;

namespace {
const char* kScene = R"([run]
end_time = 1.0
[dem]
dt = 1e-4
[[material]]
name = "g"
density = 2.0
[[contact]]
materials = ["g", "g"]
kn = 1e5
)";

std::string errorsOf(const std::string& text, const std::vector<io::Override>& ov = {}) {
    try {
        io::readSceneText(text, "s.toml", ov);
    } catch (const SceneError& e) {
        return e.what();
    }
    return "";
}
}  // namespace

TEST(SceneReader, ReadsValuesAndAppliesOverrides) {
    const auto sc = io::readSceneText(kScene, "s.toml",
                                      {io::parseOverride("dem.dt=2e-5"), io::parseOverride("dem.integrator=verlet"),
                                       io::parseOverride("contact[0].kn=3e5"), io::parseOverride("material[0].density=4")});
    EXPECT_DOUBLE_EQ(sc.dem.dt, 2e-5);
    EXPECT_EQ(sc.dem.integrator, "verlet");
    EXPECT_DOUBLE_EQ(sc.contacts[0].params.at("kn").value, 3e5);
    EXPECT_DOUBLE_EQ(sc.materials[0].density, 4.0);
    EXPECT_DOUBLE_EQ(sc.run.endTime, 1.0);
}

TEST(SceneReader, UnknownKeyHasHintAndLine) {
    const std::string err = errorsOf(std::string(kScene) + "[output]\nsnapshot_intervall = 0.1\n");
    EXPECT_NE(err.find("s.toml:12"), std::string::npos) << err;
    EXPECT_NE(err.find("did you mean 'snapshot_interval'"), std::string::npos) << err;
}

TEST(SceneReader, AllErrorsReportedTogether) {
    const std::string err = errorsOf("[run]\nend_time = \"x\"\n[dem]\ndtt = 1\n[bogus]\n");
    EXPECT_NE(err.find("end_time"), std::string::npos) << err;
    EXPECT_NE(err.find("dtt"), std::string::npos) << err;
    EXPECT_NE(err.find("bogus"), std::string::npos) << err;
}

TEST(SceneReader, OverrideOfMissingArrayElementIsAnError) {
    const std::string err = errorsOf(kScene, {io::parseOverride("contact[3].kn=1")});
    EXPECT_NE(err.find("no element [3]"), std::string::npos) << err;
    EXPECT_THROW(io::parseOverride("novalue"), SceneError);
}
