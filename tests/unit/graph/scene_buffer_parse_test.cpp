// [buffers] generator = "bvh" | "triangles": what parsing and validation accept and refuse, each
// error at the offending value.
#include "graph/parse.hpp"
#include "graph/validate.hpp"

#include <gtest/gtest.h>

using namespace pl;
using namespace pl::graph;

namespace {

const std::string kMeshes = "[meshes]\nteapot = { generator = \"teapot\" }\nfloor = { generator = \"plane\" }\n";

Result<GraphDesc> parse(const std::string& buffers) {
    return parse_graph_text(kMeshes + "[buffers]\n" + buffers + "\n", "t/preset.toml");
}

Error fails(const std::string& buffers) {
    auto g = parse(buffers);
    EXPECT_FALSE(g) << buffers;
    return g ? Error{} : g.error();
}

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

} // namespace

TEST(SceneBufferParse, Accepted) {
    auto g = parse("scene = { generator = \"bvh\", meshes = [\"teapot\", \"floor\"], leaf_size = 2 }\n"
                   "tris = { generator = \"triangles\", meshes = [\"floor\"] }");
    ASSERT_TRUE(g) << g.error().format();
    const BufferDesc* b = g->find_buffer("scene");
    ASSERT_TRUE(b);
    EXPECT_EQ(b->generator, "bvh");
    EXPECT_EQ(b->meshes, (std::vector<std::string>{"teapot", "floor"}));
    EXPECT_EQ(b->leaf_size, 2);
    EXPECT_EQ(b->keys.at("meshes.1", {}).line, 5);
    EXPECT_EQ(b->keys.at("meshes.1", {}).col, 50);
    EXPECT_TRUE(b->size.empty());
    EXPECT_EQ(g->find_buffer("tris")->leaf_size, 4);
}

TEST(SceneBufferParse, Refused) {
    Error e = fails("scene = { generator = \"bhv\", meshes = [\"teapot\"] }");
    EXPECT_TRUE(has(e.hint, "bvh")) << e.format();
    e = fails("scene = { generator = \"bvh\", meshes = [\"teapot\"], clear = 0 }");
    EXPECT_TRUE(has(e.message, "'clear' cannot be set on a generator buffer")) << e.format();
    EXPECT_EQ(e.loc.col, 51);
    e = fails("scene = { generator = \"bvh\", meshes = [\"teapot\"], history = true }");
    EXPECT_TRUE(has(e.message, "'history' cannot be set")) << e.format();
    e = fails("scene = { generator = \"bvh\", meshes = [\"teapot\"], counter = { offset = 0, capacity = 4 } }");
    EXPECT_TRUE(has(e.message, "'counter' cannot be set")) << e.format();
    e = fails("scene = { generator = \"bvh\" }");
    EXPECT_TRUE(has(e.message, "needs meshes = [")) << e.format();
    e = fails("scene = { generator = \"bvh\", meshes = [] }");
    EXPECT_TRUE(has(e.message, "non-empty array of mesh names")) << e.format();
    e = fails("scene = { generator = \"bvh\", meshes = [\"teapot\", 3] }");
    EXPECT_TRUE(has(e.message, "an element is an integer")) << e.format();
    e = fails("scene = { generator = \"bvh\", meshes = [\"teapot\", \"teapot\"] }");
    EXPECT_TRUE(has(e.message, "mesh 'teapot' is listed twice")) << e.format();
    EXPECT_EQ(e.loc.col, 50);
    e = fails("scene = { generator = \"bvh\", meshes = [\"teapot\"], leaf_size = 16 }");
    EXPECT_TRUE(has(e.message, "leaf_size")) << e.format();
    e = fails("scene = { generator = \"triangles\", meshes = [\"teapot\"], leaf_size = 2 }");
    EXPECT_TRUE(has(e.message, "leaf_size applies to generator = \"bvh\"")) << e.format();
    e = fails("scene = { generator = \"bvh\", mesh = [\"teapot\"] }");
    EXPECT_TRUE(has(e.message, "needs meshes")) << e.format();
    e = fails("scene = { generator = \"bvh\", meshes = [\"teapot\"], mehses = 1 }");
    EXPECT_TRUE(has(e.message, "unknown key 'mehses'")) << e.format();
    EXPECT_TRUE(has(e.hint, "meshes")) << e.format();
    e = fails("scene = { size = 64, meshes = [\"teapot\"] }");
    EXPECT_TRUE(has(e.message, "'meshes' describes a host-built buffer")) << e.format();
}

TEST(SceneBufferParse, UnknownMeshIsAValidationErrorAtTheName) {
    auto g = parse("scene = { generator = \"bvh\", meshes = [\"teapot\", \"flor\"] }");
    ASSERT_TRUE(g) << g.error().format();
    Status s = validate_graph(*g, {});
    ASSERT_FALSE(s);
    EXPECT_TRUE(has(s.error().message, "buffer 'scene': mesh 'flor' does not exist")) << s.error().format();
    EXPECT_EQ(s.error().loc.line, 5);
    EXPECT_EQ(s.error().loc.col, 50);
    EXPECT_TRUE(has(s.error().hint, "floor"));
    EXPECT_EQ(s.error().resource, "scene");
}

TEST(SceneBufferParse, BuiltSizeIsBoundedAtTheGeneratorKey) {
    auto g = parse("scene = { generator = \"bvh\", meshes = [\"teapot\"] }");
    ASSERT_TRUE(g) << g.error().format();
    const BufferDesc& b = *g->find_buffer("scene");
    EXPECT_TRUE(check_built_buffer_size(b, int64_t(1) << 30));
    Status s = check_built_buffer_size(b, (int64_t(1) << 30) + 16);
    ASSERT_FALSE(s);
    EXPECT_TRUE(has(s.error().message, "buffer 'scene': the bvh build needs 1073741840 bytes (limit 1.0 GiB)")) << s.error().format();
    EXPECT_EQ(s.error().loc.line, 5);
    EXPECT_EQ(s.error().loc.col, 23);
}
