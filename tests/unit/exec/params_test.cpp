// [params] -> std140 block: offsets must match what glslang lays out for the generated GLSL.
#include "exec/params.hpp"

#include <gtest/gtest.h>

#include <cstring>

using namespace pl;
using namespace pl::exec;

namespace {
graph::ParamDesc param(const std::string& n, graph::ParamType t, std::array<double, 4> v = {}) {
    graph::ParamDesc p;
    p.name = n;
    p.type = t;
    p.value = v;
    return p;
}
} // namespace

TEST(Params, Std140Offsets) {
    std::vector<graph::ParamDesc> ps = {param("a", graph::ParamType::f32), param("b", graph::ParamType::vec3),
                                        param("c", graph::ParamType::f32), param("d", graph::ParamType::vec2),
                                        param("e", graph::ParamType::vec4), param("f", graph::ParamType::i32)};
    auto L = layout_params(ps);
    ASSERT_EQ(L.slots.size(), 6u);
    EXPECT_EQ(L.slots[0].offset, 0u);
    EXPECT_EQ(L.slots[1].offset, 16u);  // vec3 aligns to 16
    EXPECT_EQ(L.slots[2].offset, 28u);  // a float fits in the vec3's tail
    EXPECT_EQ(L.slots[3].offset, 32u);  // vec2 aligns to 8
    EXPECT_EQ(L.slots[4].offset, 48u);
    EXPECT_EQ(L.slots[5].offset, 64u);
    EXPECT_EQ(L.size, 80u);
}

TEST(Params, PackAndOverride) {
    std::vector<graph::ParamDesc> ps = {param("gain", graph::ParamType::f32, {1.0}),
                                        param("count", graph::ParamType::i32, {3})};
    ps[0].min = 0.0;
    ps[0].max = 2.0;
    ASSERT_TRUE(apply_param_override(ps, "gain=1.5"));
    ASSERT_TRUE(apply_param_override(ps, "count=7"));
    auto bytes = pack_params(ps, layout_params(ps));
    float g;
    int32_t c;
    std::memcpy(&g, bytes.data(), 4);
    std::memcpy(&c, bytes.data() + 4, 4);
    EXPECT_FLOAT_EQ(g, 1.5f);
    EXPECT_EQ(c, 7);
}

TEST(Params, OverrideErrors) {
    std::vector<graph::ParamDesc> ps = {param("gain", graph::ParamType::f32, {1.0})};
    ps[0].max = 2.0;
    auto out = apply_param_override(ps, "gain=5");
    ASSERT_FALSE(out);
    EXPECT_NE(out.error().message.find("value 5 is above its max 2"), std::string::npos) << out.error().message;
    auto unknown = apply_param_override(ps, "gian=1");
    ASSERT_FALSE(unknown);
    EXPECT_EQ(unknown.error().hint, "did you mean 'gain'?");
    auto usage = apply_param_override(ps, "gain");
    ASSERT_FALSE(usage);
    EXPECT_EQ(usage.error().code, ExitCode::usage);
}

TEST(Params, EnumByName) {
    auto p = param("model", graph::ParamType::enumeration);
    p.options = {"phong", "blinn"};
    std::vector<graph::ParamDesc> ps = {p};
    ASSERT_TRUE(apply_param_override(ps, "model=blinn"));
    EXPECT_EQ(ps[0].value[0], 1.0);
    EXPECT_NE(params_glsl(ps).find("#define MODEL_BLINN 1"), std::string::npos);
    EXPECT_FALSE(apply_param_override(ps, "model=phon"));
}

// `--set` pins a param against the sidecar and the wall clock only when it names exactly that
// param: "gain" is not set by "gaink=2", nor by a bare "gain".
TEST(Params, AssignsMatchesWholeNames) {
    EXPECT_TRUE(assigns({"octaves=3", "gain=0.5"}, "gain"));
    EXPECT_TRUE(assigns({"gain="}, "gain"));
    EXPECT_FALSE(assigns({"gaink=2"}, "gain"));
    EXPECT_FALSE(assigns({"gain"}, "gain"));
    EXPECT_FALSE(assigns({}, "gain"));
}
