// [cameras]: parsing (types, keys per camera type, test overrides) and evaluation (expressions,
// ranges, located errors).
#include "graph/camera_values.hpp"
#include "graph/parse.hpp"
#include "graph/validate.hpp"

#include <gtest/gtest.h>

#include <cmath>

using namespace pl;
using namespace pl::graph;

namespace {

const char* kBase = R"([params]
dir = [0.0, 1.0, 0.0]
[images]
ldr = { format = "rgba8", size = [4, 4] }
[[pass]]
name = "p"
fragment = "debug/uv.frag"
targets = ["ldr"]
)";

Result<GraphDesc> parse(const std::string& cameras, const std::string& rest = "") {
    return parse_graph_text(std::string(kBase) + "[cameras]\n" + cameras + "\n" + rest, "t/preset.toml");
}

Error parse_error(const std::string& cameras, const std::string& rest = "") {
    auto g = parse(cameras, rest);
    EXPECT_FALSE(g) << cameras;
    return g ? Error{} : g.error();
}

Result<CameraValues> eval(const GraphDesc& g, size_t i = 0) { return eval_camera(g.cameras[i], make_env(g, {640, 360})); }

} // namespace

TEST(Cameras, LiteralsExpressionsAndDefaults) {
    auto g = parse(R"(sun = { ortho = true, eye = "params.dir * 10", target = [0, 0, 0], up = [0, 0, -1], ortho_height = 8 }
spot = { eye = [0, 0, "2 + 3"], target = [0, 0, 0], fov = "45 * 2", far = inf }
probe = { cube = true, eye = [1, 2, 3] })");
    ASSERT_TRUE(g) << g.error().format();
    ASSERT_EQ(g->cameras.size(), 3u);
    EXPECT_EQ(g->cameras[0].name, "sun");  // declaration order
    auto sun = eval(*g, 0);
    ASSERT_TRUE(sun) << sun.error().format();
    EXPECT_EQ(sun->eye, (std::array<double, 3>{0, 10, 0}));
    EXPECT_TRUE(sun->ortho);
    EXPECT_EQ(sun->ortho_height, 8);
    EXPECT_EQ(sun->near, 0.05);
    auto spot = eval(*g, 1);
    ASSERT_TRUE(spot);
    EXPECT_EQ(spot->eye[2], 5);
    EXPECT_EQ(spot->fov, 90);
    EXPECT_TRUE(std::isinf(spot->far));
    EXPECT_EQ(spot->aspect, 1);
    auto probe = eval(*g, 2);
    ASSERT_TRUE(probe);
    EXPECT_TRUE(probe->cube);
    EXPECT_EQ(probe->fov, 90);
}

TEST(Cameras, KeysOfAnotherTypeAreErrors) {
    Error e = parse_error("s = { ortho = true, eye = [0, 1, 0], target = [0, 0, 0], fov = 30 }");
    EXPECT_NE(e.message.find("'fov' does not apply to an ortho camera"), std::string::npos) << e.format();
    EXPECT_EQ(e.loc.line, 10);
    e = parse_error("c = { cube = true, eye = [0, 1, 0], target = [0, 0, 0] }");
    EXPECT_NE(e.message.find("'target' does not apply to a cube camera"), std::string::npos) << e.format();
    e = parse_error("c = { eye = [0, 1, 0], taget = [0, 0, 0] }");
    EXPECT_NE(e.message.find("unknown key 'taget'"), std::string::npos) << e.format();
    EXPECT_NE(e.hint.find("target"), std::string::npos);
    e = parse_error("c = { eye = [0, 1], target = [0, 0, 0] }");
    EXPECT_NE(e.message.find("3 components"), std::string::npos) << e.format();
    e = parse_error("c = { eye = [0, 1, 0] }");
    EXPECT_NE(e.message.find("needs target"), std::string::npos) << e.format();
    e = parse_error("uniform = { eye = [0, 1, 0], target = [0, 0, 0] }");
    EXPECT_NE(e.message.find("GLSL keyword"), std::string::npos) << e.format();
}

TEST(Cameras, ValuesAreCheckedAtTheirKey) {
    auto check = [](const std::string& cam, const std::string& want, int col) {
        auto g = parse(cam);
        ASSERT_TRUE(g) << g.error().format();
        auto v = eval(*g);
        ASSERT_FALSE(v) << cam;
        EXPECT_NE(v.error().message.find(want), std::string::npos) << v.error().format();
        EXPECT_EQ(v.error().loc.line, 10) << cam;
        if (col) {
            EXPECT_EQ(v.error().loc.col, col) << v.error().format();
        }
    };
    check("c = { eye = [0, 1, 0], target = [0, 0, 0], near = 0 }", "near must be > 0", 51);
    check("c = { eye = [0, 1, 0], target = [0, 0, 0], near = 2, far = 1 }", "far must be greater than near", 0);
    check("c = { eye = [0, 1, 0], target = [0, 0, 0], far = nan }", "far must be greater than near", 0);
    check("c = { eye = [0, 1, 0], target = [0, 0, 0], fov = 180 }", "fov must be between 0 and 180", 0);
    check("c = { ortho = true, eye = [0, 1, 0], target = [0, 0, 0], far = inf }", "finite for an ortho camera", 0);
    check("c = { eye = [0, 1, 0], target = [0, 1, 0] }", "is the eye", 0);
    check("c = { eye = \"params.dir\", target = [0, 0, 0], up = [0, 0, 0] }", "up must not be zero", 0);
    // An unknown param in an expression: at its token, with the suggestion.
    check("c = { eye = \"params.dri * 10\", target = [0, 0, 0] }", "unknown name 'params.dri'", 14);
    check("c = { eye = \"params.dir.x\", target = [0, 0, 0] }", "evaluates to 1", 0);
}

TEST(Cameras, TestOverridesStartFromTheGraphsCamera) {
    auto g = parse("sun = { ortho = true, eye = [0, 10, 0], target = [0, 0, 0], near = 1, far = 21 }",
                   "[[test]]\nname = \"t\"\ncameras = { sun = { eye = [0, 12, 0] } }\n");
    ASSERT_TRUE(g) << g.error().format();
    const CameraDesc& c = g->tests[0].cameras.at("sun");
    auto v = eval_camera(c, make_env(*g, {4, 4}));
    ASSERT_TRUE(v);
    EXPECT_EQ(v->eye[1], 12);
    EXPECT_EQ(v->far, 21);  // kept
    EXPECT_TRUE(v->ortho);
    Error e = parse_error("sun = { eye = [0, 10, 0], target = [0, 0, 0] }", "[[test]]\nname = \"t\"\ncameras = { sunn = { eye = [0, 1, 0] } }\n");
    EXPECT_NE(e.message.find("camera 'sunn' does not exist"), std::string::npos) << e.format();
    EXPECT_NE(e.hint.find("sun"), std::string::npos);
    e = parse_error("sun = { ortho = true, eye = [0, 10, 0], target = [0, 0, 0] }", "[[test]]\nname = \"t\"\ncameras = { sun = { fov = 3 } }\n");
    EXPECT_NE(e.message.find("'fov' does not apply to an ortho camera"), std::string::npos) << e.format();
}

TEST(Cameras, TooManyEntriesForTheBlock) {
    std::string many;
    for (int i = 0; i < 7; ++i) many += "c" + std::to_string(i) + " = { cube = true, eye = [0, 0, 0] }\n";
    Error e = parse_error(many);  // 42 > 39 entries
    EXPECT_NE(e.message.find("at most 39"), std::string::npos) << e.format();
}
