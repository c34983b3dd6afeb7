// The live lab's saved param values: what the panel saves, the next run reads back unchanged.
#include "exec/param_sidecar.hpp"
#include "exec/params.hpp"

#include <gtest/gtest.h>

#include <fstream>

using namespace pl;
namespace fs = std::filesystem;

namespace {
graph::ParamDesc param(const std::string& n, graph::ParamType t, std::array<double, 4> v = {}) {
    graph::ParamDesc p;
    p.name = n;
    p.type = t;
    p.value = v;
    return p;
}
fs::path temp_dir() {
    fs::path d = fs::temp_directory_path() / ("passlab-sidecar-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                              ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::create_directories(d);
    return d;
}
} // namespace

TEST(ParamSidecar, PathSitsBesideThePreset) {
    EXPECT_EQ(exec::sidecar_path("/a/b/preset.toml"), fs::path("/a/b/preset.params.toml"));
}

TEST(ParamSidecar, RoundTripEveryType) {
    auto mode = param("mode", graph::ParamType::enumeration, {1});
    mode.options = {"lit", "furnace"};
    std::vector<graph::ParamDesc> ps = {param("gain", graph::ParamType::f32, {0.25}), param("count", graph::ParamType::i32, {7}),
                                        param("on", graph::ParamType::boolean, {1}), param("albedo", graph::ParamType::color3, {0.8, 0.5, 0.125}),
                                        mode, param("untouched", graph::ParamType::f32, {3})};
    std::map<std::string, std::array<double, 4>> touched;
    for (const auto& p : ps)
        if (p.name != "untouched") touched[p.name] = p.value;
    fs::path file = temp_dir() / "preset.params.toml";
    ASSERT_TRUE(exec::save_sidecar(file, ps, touched));
    EXPECT_FALSE(fs::exists(file.string() + ".tmp"));  // written by rename

    auto sets = exec::load_sidecar(file);
    ASSERT_TRUE(sets) << sets.error().format();
    EXPECT_EQ(sets->size(), 5u);  // only what was touched
    // Applied to the preset's defaults, the saved values come back exactly.
    std::vector<graph::ParamDesc> fresh = ps;
    for (auto& p : fresh) p.value = {};
    fresh[5].value = {3};
    for (const auto& a : *sets) ASSERT_TRUE(exec::apply_param_override(fresh, a)) << a;
    for (size_t i = 0; i < ps.size(); ++i)
        for (int c = 0; c < ps[i].components(); ++c) EXPECT_DOUBLE_EQ(fresh[i].value[size_t(c)], ps[i].value[size_t(c)]) << ps[i].name;
    fs::remove_all(file.parent_path());
}

TEST(ParamSidecar, MissingFileIsEmptyAndBadLineIsLocated) {
    auto none = exec::load_sidecar("/nonexistent/preset.params.toml");
    ASSERT_TRUE(none);
    EXPECT_TRUE(none->empty());
    fs::path file = temp_dir() / "preset.params.toml";
    std::ofstream(file) << "# saved\ngain = 0.5\nthis line has no equals sign\n";
    auto bad = exec::load_sidecar(file);
    ASSERT_FALSE(bad);
    EXPECT_EQ(bad.error().loc.line, 3);
    fs::remove_all(file.parent_path());
}
