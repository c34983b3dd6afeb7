// Validation: references with suggestions at the exact line, formats, pass kinds, shader files,
// sizes and memory before allocation, default output, test cases.
#include "graph/parse.hpp"
#include "graph/validate.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace pl;
using namespace pl::graph;

namespace {

const fs::path kData = fs::path(PASSLAB_TEST_DIR) / "unit" / "graph" / "data";

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// 1-based line and column of the first occurrence of `needle` in `text`.
int line_of(const std::string& text, const std::string& needle) {
    size_t at = text.find(needle);
    EXPECT_NE(at, std::string::npos) << needle;
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}
int col_of(const std::string& text, const std::string& needle) {
    size_t at = text.find(needle);
    size_t start = text.rfind('\n', at);
    return static_cast<int>(at - (start == std::string::npos ? 0 : start + 1)) + 1;
}

GraphDesc parse(const std::string& text) {
    auto g = parse_graph_text(text, kData / "preset.toml");  // shaders resolve from data/, then passes/
    EXPECT_TRUE(g) << text << "\n" << (g ? "" : g.error().format());
    return g ? *g : GraphDesc{};
}

// The validation error of `text`, which must parse and then fail to validate.
Error invalid(const std::string& text, ValidateOptions opt = {}) {
    GraphDesc g = parse(text);
    auto s = validate_graph(static_cast<const GraphDesc&>(g), opt);
    EXPECT_FALSE(s) << text;
    return s ? Error{} : s.error();
}

Status valid(const std::string& text, ValidateOptions opt = {}) {
    GraphDesc g = parse(text);
    return validate_graph(static_cast<const GraphDesc&>(g), opt);
}

// One fullscreen pass into `ldr`, after `extra`.
std::string with_pass(const std::string& extra, const std::string& images = "ldr = {}") {
    return "[images]\n" + images + "\n" + extra + "\n[[pass]]\nname = \"main\"\nfragment = \"debug/uv.frag\"\ntargets = [\"ldr\"]\n";
}

} // namespace

TEST(Validate, FullPresetIsValid) {
    auto g = parse_graph_file(kData / "full.toml");
    ASSERT_TRUE(g) << g.error().format();
    auto s = validate_graph(*g, {});
    EXPECT_TRUE(s) << s.error().format();
    EXPECT_EQ(g->output, "ldr");
    ValidateOptions small;
    small.view_size = std::array<int, 2>{16, 16};
    EXPECT_TRUE(validate_graph(*g, small));
}

TEST(Validate, UnknownTargetSuggestsNearestAndNamesPassAndLine) {
    Error e = invalid("[images]\nalbedo = { format = \"rgba8\" }\nnormal = { format = \"rgba16f\" }\n\n[[pass]]\nname = \"gbuf\"\n"
                      "fragment = \"debug/uv.frag\"\ntargets = [\"normal\", \"albdo\"]\n");
    EXPECT_EQ(e.message, "image 'albdo' does not exist");
    EXPECT_EQ(e.pass, "gbuf");
    EXPECT_EQ(e.resource, "albdo");
    EXPECT_EQ(e.loc.line, 8);
    EXPECT_EQ(e.loc.col, 22);
    EXPECT_EQ(e.hint, "did you mean 'albedo'?");
    ASSERT_FALSE(e.notes.empty());
    EXPECT_EQ(e.notes[0], "images: albedo, normal");
    EXPECT_EQ(e.source_line, "");  // parse_graph_text of a file that does not exist
    EXPECT_TRUE(has(e.format(), "preset.toml:8:22: error: image 'albdo' does not exist [pass 'gbuf', resource 'albdo']"));
}

TEST(Validate, EveryReferenceIsChecked) {
    struct Case {
        std::string text;
        const char* says;
        const char* hint;
        const char* at;  // the text the error points at
    };
    const std::string shadow_img = "ldr = {}\nshadow = { format = \"d32s8\" }\nbuf = { size = 16 }";
    std::vector<Case> cases = {
        {with_pass("[[pass]]\nname = \"d\"\nkind = \"draw\"\nvertex = \"test/quad.vert\"\nvertex_count = 3\ndepth = \"shadw\"\n",
                   "ldr = {}\nshadow = { format = \"d32\" }"),
         "depth image 'shadw' does not exist", "did you mean 'shadow'?", "\"shadw\""},
        {with_pass("[[pass]]\nname = \"d\"\nkind = \"draw\"\nvertex = \"test/quad.vert\"\nmesh = \"bal\"\ntargets = [\"ldr\"]\n"
                   "[meshes]\nball = { generator = \"sphere\" }\n"),
         "mesh 'bal' does not exist", "did you mean 'ball'?", "\"bal\""},
        {with_pass("[buffers]\nargs = { size = 16 }\n[[pass]]\nname = \"c\"\nkind = \"compute\"\ncompute = \"test/scale_inplace.comp\"\n"
                   "indirect = \"arg\"\n"),
         "indirect buffer 'arg' does not exist", "did you mean 'args'?", "\"arg\""},
        {with_pass("[[pass]]\nname = \"b\"\nkind = \"blit\"\nsrc = \"lrd\"\ndst = \"ldr\"\n"), "src image 'lrd' does not exist",
         "did you mean 'ldr'?", "\"lrd\""},
        {with_pass("[[pass]]\nname = \"b\"\nkind = \"blit\"\nsrc = \"ldr\"\ndst = \"ld\"\n"), "dst image 'ld' does not exist",
         "did you mean 'ldr'?", "\"ld\""},
        {with_pass("[[pass]]\nname = \"m\"\nkind = \"mips\"\nimage = \"ldrr\"\n"), "image 'ldrr' does not exist", "did you mean 'ldr'?", "\"ldrr\""},
        {with_pass("[[pass]]\nname = \"c\"\nkind = \"clear\"\nimage = \"bufs\"\n", shadow_img), "image or buffer 'bufs' does not exist",
         "did you mean 'buf'?", "\"bufs\""},
        {with_pass("[[pass]]\nname = \"p\"\nfragment = \"debug/uv.frag\"\ntargets = [\"ldr2\"]\nbind = { src = \"ldrr\" }\n",
                   "ldr = {}\nldr2 = {}"),
         "bind target 'ldrr' does not exist", "did you mean 'ldr'?", "\"ldrr\""},
        {with_pass("[[pass]]\nname = \"p\"\nkind = \"compute\"\ncompute = \"test/scale_inplace.comp\"\ngroups = 1\nrepeat = 2\n"
                   "swap = [\"ldr\", \"ldrr\"]\n"),
         "swap image 'ldrr' does not exist", "did you mean 'ldr'?", "[\"ldr\", \"ldrr\"]"},
        {with_pass("[[pass]]\nname = \"p\"\nfragment = \"debug/uv.frag\"\ntargets = [{ image = \"msaa\", resolve = \"lrd\" }]\n",
                   "ldr = {}\nmsaa = { samples = 4 }"),
         "resolve image 'lrd' does not exist", "did you mean 'ldr'?", "\"lrd\""},
        {with_pass("[output]\nimage = \"lrd\"\n"), "output image 'lrd' does not exist", "did you mean 'ldr'?", "\"lrd\""},
        {"[images]\nldr = {}\nview2 = { alias = \"lrd\" }\n", "alias target image 'lrd' does not exist", "did you mean 'ldr'?", "\"lrd\""},
    };
    for (const Case& c : cases) {
        Error e = invalid(c.text);
        EXPECT_TRUE(has(e.message, c.says)) << c.text << e.format();
        EXPECT_EQ(e.hint, c.hint) << c.text;
        EXPECT_EQ(e.loc.line, line_of(c.text, c.at)) << c.text << e.format();
        EXPECT_EQ(e.loc.col, col_of(c.text, c.at)) << c.text << e.format();
        EXPECT_FALSE(e.notes.empty()) << c.text;
    }
}

TEST(Validate, AttachmentFormatsAndSharing) {
    Error colour_depth = invalid(with_pass("[[pass]]\nname = \"z\"\nfragment = \"debug/uv.frag\"\ntargets = [\"d\"]\n",
                                           "ldr = {}\nd = { format = \"d32\" }"));
    EXPECT_TRUE(has(colour_depth.message, "has a depth format")) << colour_depth.message;
    EXPECT_EQ(colour_depth.loc.line, 7);
    Error depth_colour = invalid(with_pass("[[pass]]\nname = \"z\"\nfragment = \"debug/uv.frag\"\ntargets = [\"ldr\"]\ndepth = \"c\"\n",
                                           "ldr = {}\nc = { format = \"rgba8\" }"));
    EXPECT_TRUE(has(depth_colour.message, "depth image 'c' has the colour format rgba8")) << depth_colour.message;
    EXPECT_EQ(depth_colour.loc.line, 8);
    Error twice = invalid(with_pass("[[pass]]\nname = \"z\"\nfragment = \"debug/uv.frag\"\ntargets = [\"a\", \"b\"]\n",
                                    "ldr = {}\na = {}\nb = { alias = \"a\" }"));
    EXPECT_TRUE(has(twice.message, "image 'b' is attached twice (it is an alias of 'a')")) << twice.message;
    Error stencil = invalid(with_pass("[[pass]]\nname = \"z\"\nfragment = \"debug/uv.frag\"\ntargets = [\"ldr\"]\ndepth = \"d\"\n"
                                      "stencil = { reference = 1 }\n",
                                      "ldr = {}\nd = { format = \"d32\" }"));
    EXPECT_TRUE(has(stencil.message, "stencil needs a depth image with stencil")) << stencil.message;
    EXPECT_EQ(stencil.loc.line, 9);
    for (const char* bad : {
             "targets = [{ image = \"ldr\", resolve = \"ldr2\" }]",        // single-sampled target
             "targets = [{ image = \"msaa\", resolve = \"msaa2\" }]",      // multisampled resolve
             "targets = [{ image = \"msaa\", resolve = \"hdr\" }]",       // format differs
             "targets = [{ image = \"ldr\", layer = 1 }]",                 // one layer
             "targets = [{ image = \"arr\", layer = 4 }]",                 // layers 0..3
             "targets = [{ image = \"ldr\", layer = \"all\" }]",
             "targets = [{ image = \"ldr\", mip = 1 }]",                   // one mip
             "targets = [\"grid\"]",                                       // generator image
             "targets = [\"ldr\"]\nblend = [\"alpha\", \"off\"]",          // 2 modes for 1 target
             "targets = [\"ldr\"]\nclear = { depth = 1.0 }",               // no depth attachment
             "clear = { color = [0, 0, 0, 0] }\ndepth = \"d\"",            // no colour target
             "depth = \"d\"\nstencil = {}\n",                              // d32: no stencil
             "blend = \"alpha\"",                                          // renders into nothing
         }) {
        Error e = invalid("[images]\nldr = {}\nldr2 = {}\nmsaa = { samples = 4 }\nmsaa2 = { samples = 4 }\nhdr = { format = \"rgba16f\" }\n"
                          "arr = { kind = \"2d-array\", layers = 4 }\ngrid = { generator = \"checker\" }\nd = { format = \"d32\" }\n"
                          "[[pass]]\nname = \"p\"\nfragment = \"debug/uv.frag\"\n" +
                          std::string(bad) + "\n");
        EXPECT_EQ(e.pass, "p") << bad;
        EXPECT_GE(e.loc.line, 11) << bad << e.format();
    }
}

TEST(Validate, KindRequirements) {
    struct Case {
        const char* pass;
        const char* says;
    };
    for (const Case& c : {
             Case{"targets = [\"ldr\"]", "a fullscreen pass needs fragment"},
             Case{"kind = \"draw\"\nfragment = \"debug/uv.frag\"\nvertex_count = 3\ntargets = [\"ldr\"]", "a draw pass needs vertex"},
             Case{"kind = \"draw\"\nvertex = \"test/quad.vert\"\ntargets = [\"ldr\"]", "needs mesh"},
             Case{"kind = \"compute\"\ncompute = \"test/scale_inplace.comp\"", "needs groups"},
             Case{"kind = \"compute\"\ncompute = \"test/scale_inplace.comp\"\ngroups = 1\nthreads = 1", "not both"},
             Case{"kind = \"compute\"\ngroups = 1", "a compute pass needs compute"},
             Case{"kind = \"blit\"\nsrc = \"ldr\"", "needs src = \"name\" and dst"},
             Case{"kind = \"copy\"\ndst = \"ldr\"", "needs src = \"name\" and dst"},
             Case{"kind = \"mips\"", "a mips pass needs image"},
             Case{"kind = \"clear\"", "a clear pass needs image"},
             Case{"kind = \"compute\"\ncompute = \"test/scale_inplace.comp\"\ngroups = 1\nfragment = \"debug/uv.frag\"", "'fragment' does not apply to a compute pass"},
             Case{"fragment = \"debug/uv.frag\"\ncompute = \"test/scale_inplace.comp\"\ntargets = [\"ldr\"]", "'compute' does not apply to a fullscreen pass"},
             Case{"fragment = \"debug/uv.frag\"\ngeometry = \"local.geom\"\ntargets = [\"ldr\"]", "'geometry' does not apply to a fullscreen pass"},
             Case{"kind = \"blit\"\nsrc = \"ldr\"\ndst = \"ldr2\"\nvertex = \"test/quad.vert\"", "'vertex' does not apply to a blit pass"},
             Case{"fragment = \"debug/uv.frag\"\ntargets = [\"ldr\"]\ngroups = 4", "'groups' does not apply to a fullscreen pass"},
             Case{"fragment = \"debug/uv.frag\"\ntargets = [\"ldr\"]\nmesh = \"m\"", "'mesh' does not apply to a fullscreen pass"},
             Case{"kind = \"compute\"\ncompute = \"test/scale_inplace.comp\"\ngroups = 1\ntargets = [\"ldr\"]", "'targets' does not apply"},
             Case{"kind = \"copy\"\nsrc = \"ldr\"\ndst = \"ldr2\"\nfilter = \"nearest\"", "'filter' does not apply to a copy pass"},
             Case{"kind = \"draw\"\nvertex = \"test/quad.vert\"\nvertex_count = 3\ntess_eval = \"local.tese\"\ntargets = [\"ldr\"]", "both tess_control and tess_eval"},
             Case{"kind = \"draw\"\nvertex = \"test/quad.vert\"\nvertex_count = 3\ntess_control = \"local.tesc\"\ntess_eval = \"local.tese\"\ntargets = [\"ldr\"]", "topology = \"patches\""},
             Case{"kind = \"blit\"\nsrc = \"ldr\"\ndst = \"ldr\"", "src and dst are the same"},
             Case{"kind = \"copy\"\nsrc = \"buf\"\ndst = \"ldx\"", "dst image or buffer 'ldx' does not exist"},
             Case{"kind = \"mips\"\nimage = \"ldr\"", "has one mip"},
             Case{"kind = \"compute\"\ncompute = \"test/scale_inplace.comp\"\ngroups = 1\nswap = [\"ldr\", \"ldr2\"]", "add repeat"},
         }) {
        Error e = invalid("[images]\nldr = {}\nldr2 = {}\n[buffers]\nbuf = { size = 16 }\n[meshes]\nm = { generator = \"cube\" }\n"
                          "[[pass]]\nname = \"p\"\n" + std::string(c.pass) + "\n");
        EXPECT_TRUE(has(e.message, c.says)) << c.pass << "\n" << e.format();
        EXPECT_EQ(e.pass, "p") << c.pass;
        EXPECT_GE(e.loc.line, 9) << c.pass;
    }
    Error groups = invalid(with_pass("[[pass]]\nname = \"p\"\nfragment = \"debug/uv.frag\"\ntargets = [\"ldr\"]\ngroups = 4\n"));
    EXPECT_EQ(groups.hint, "'groups' belongs to kind = \"compute\"");
    EXPECT_EQ(groups.loc.line, 7);
    EXPECT_EQ(groups.loc.col, 10);
}

TEST(Validate, MissingShaderIsReportedAtItsKey) {
    Error e = invalid("[images]\nx = {}\n[[pass]]\nname = \"a\"\nfragment = \"debug/uvv.frag\"\ntargets = [\"x\"]\n");
    EXPECT_EQ(e.message, "the shader 'debug/uvv.frag' not found");
    EXPECT_EQ(e.pass, "a");
    EXPECT_EQ(e.loc.line, 5);
    EXPECT_EQ(e.loc.col, 12);
    EXPECT_EQ(e.hint, "did you mean 'debug/uv.frag'?");
    bool looked = false;
    for (const auto& n : e.notes) looked |= has(n, "looked in") && has(n, "passes");
    EXPECT_TRUE(looked);
    ValidateOptions only_data;
    only_data.search_dirs = {kData};  // passes/ not searched: debug/uv.frag is not found
    Error d = invalid("[images]\nx = {}\n[[pass]]\nname = \"a\"\nfragment = \"debug/uv.frag\"\ntargets = [\"x\"]\n", only_data);
    EXPECT_TRUE(has(d.message, "debug/uv.frag"));
}

TEST(Validate, ShaderSearchOrderIsPresetThenPasses) {
    GraphDesc g = parse("");
    fs::path found = resolve_shader_path(g, "local.geom", {});
    EXPECT_EQ(found, kData / "local.geom");
    EXPECT_EQ(resolve_shader_path(g, "debug/uv.frag", {}), passes_dir() / "debug/uv.frag");
    EXPECT_TRUE(resolve_shader_path(g, "nope.frag", {}).empty());
    // A file in the preset folder shadows the library's.
    fs::path dir = fs::temp_directory_path() / ("passlab-graph-test-" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    fs::create_directories(dir / "debug");
    std::ofstream(dir / "debug" / "uv.frag") << "#version 450\nvoid main() {}\n";
    auto local = parse_graph_text("", dir / "preset.toml");
    ASSERT_TRUE(local);
    EXPECT_EQ(resolve_shader_path(*local, "debug/uv.frag", {}), dir / "debug" / "uv.frag");
    EXPECT_EQ(default_search_dirs(*local).front(), fs::absolute(dir));
    fs::remove_all(dir);
}

TEST(Validate, SizesAreCheckedBeforeAllocation) {
    struct Case {
        const char* image;
        const char* says;
        const char* at;  // the text the error points at
    };
    for (const Case& c : {
             Case{"big = { size = [0, 360] }", "image 'big': size evaluates to 0x360; every side must be at least 1", "size = "},
             Case{"big = { size = \"view - view / view * view.w\" }", "size evaluates to 0x-280", "size = "},
             Case{"big = { size = -5 }", "size evaluates to -5x-5", "size = "},
             Case{"big = { size = [100000, 100000] }", "size evaluates to 100000x100000; sides are limited to 16384", "size = "},
             Case{"big = { size = \"view * 100\" }", "size evaluates to 64000x36000", "size = "},
             Case{"big = { kind = \"3d\", size = [4096, 4, 4] }", "sides are limited to 2048 for 3D images", "size = "},
             Case{"big = { kind = \"3d\", size = 2048, format = \"r8\" }", "would need 8.0 GiB", "size = "},
             Case{"big = { format = \"rgba32f\", size = [16384, 16384] }", "image 'big': would need 4.0 GiB (limit 2.0 GiB)", "size = "},
             Case{"big = { format = \"rgba32f\", size = [16384, 12800] }", "would need 3.1 GiB", "size = "},
             Case{"big = { format = \"rgba16f\", size = [16384, 8200], history = true }", "would need 2.0 GiB", "size = "},
             Case{"big = { kind = \"cube\", size = [64, 32] }", "a cube image must be square, not 64x32", "size = "},
             Case{"big = { size = [64, 64, 64] }", "a 2D size has 1 or 2 components", "size = "},
             Case{"big = { size = \"view.w / params.n\" }", "unknown name 'params.n'", "params.n"},
         }) {
        Error e = invalid(with_pass("", std::string("ldr = {}\n") + c.image));
        EXPECT_TRUE(has(e.message, c.says)) << c.image << "\n" << e.format();
        EXPECT_EQ(e.resource, "big") << c.image;
        EXPECT_EQ(e.loc.line, 3) << c.image;
        int want = col_of(c.image, c.at) + (std::string(c.at) == "size = " ? 7 : 0);  // the value after "size = "
        EXPECT_EQ(e.loc.col, want) << c.image << "\n" << e.format();
    }
    Error mem = invalid(with_pass("", "ldr = {}\nbig = { format = \"rgba32f\", size = [16384, 16384] }"));
    ASSERT_FALSE(mem.notes.empty());
    EXPECT_EQ(mem.notes[0], "16384x16384 x 16 bytes per texel");

    for (auto [buffer, says] : {std::pair<const char*, const char*>{"b = { size = \"view.w * view.h * 100000\" }",
                                                                    "buffer 'b': size evaluates to 23040000000 bytes; it must be between 4 bytes and 1.0 GiB"},
                                {"b = { size = 0 }", "size evaluates to 0 bytes"},
                                {"b = { size = \"view\" }", "expected a single number"},
                                {"b = { size = 8, data = [1, 2, 3] }", "data holds 12 bytes but the buffer has 8"}}) {
        Error e = invalid(with_pass(std::string("[buffers]\n") + buffer));
        EXPECT_TRUE(has(e.message, says)) << buffer << "\n" << e.format();
        EXPECT_EQ(e.resource, "b");
        EXPECT_EQ(e.loc.line, 4) << buffer;
        EXPECT_GT(e.loc.col, 5) << buffer;
    }

    for (auto [pass, says] : {std::pair<const char*, const char*>{"groups = \"view / 1000\"", "groups evaluates to 0x0"},
                              {"groups = 100000", "components are limited to 65535"},
                              {"threads = \"view - 640\"", "threads evaluates to 0x-280"},
                              {"groups = 1\nrepeat = 0", "repeat evaluates to 0"},
                              {"groups = 1\nrepeat = \"view\"", "expected a single number"}}) {
        Error e = invalid(with_pass(std::string("[[pass]]\nname = \"c\"\nkind = \"compute\"\ncompute = \"test/scale_inplace.comp\"\n") + pass));
        EXPECT_TRUE(has(e.message, says)) << pass << "\n" << e.format();
        EXPECT_EQ(e.pass, "c");
    }
}

TEST(Validate, ViewSizeOverrideAndTestSizes) {
    std::string text = with_pass("", "ldr = { size = \"view / 16\" }");
    ValidateOptions tiny;
    tiny.view_size = std::array<int, 2>{8, 8};
    Error e = invalid(text, tiny);
    EXPECT_TRUE(has(e.message, "size evaluates to 0x0")) << e.message;
    tiny.view_size = std::array<int, 2>{16, 16};
    EXPECT_TRUE(valid(text, tiny));

    Error t = invalid(text + "[[test]]\nname = \"small\"\nsize = [32, 8]\n");
    EXPECT_TRUE(has(t.message, "size evaluates to 2x0")) << t.message;
    EXPECT_EQ(t.loc.line, 2);  // the size expression
    ASSERT_FALSE(t.notes.empty());
    EXPECT_TRUE(has(t.notes.back(), "in test 'small' (32x8) at ")) << t.notes.back();
    ValidateOptions no_tests;
    no_tests.per_test_sizes = false;
    EXPECT_TRUE(valid(text + "[[test]]\nname = \"small\"\nsize = [32, 8]\n", no_tests));

    // A test's param overrides feed size expressions too.
    Error p = invalid(with_pass("[params]\ndiv = { value = 2, min = 1, max = 1000 }\n", "ldr = { size = \"view / params.div\" }") +
                      "[[test]]\nname = \"coarse\"\nset = { div = 1000 }\n");
    EXPECT_TRUE(has(p.message, "size evaluates to 0x0")) << p.message;
}

TEST(Validate, ImageRules) {
    struct Case {
        const char* images;
        const char* says;
    };
    for (const Case& c : {
             Case{"p = { alias = \"q\" }\nq = { alias = \"ldr\" }", "'q' is itself an alias"},
             Case{"p = { alias = \"p\" }", "alias target image 'p' does not exist"},
             Case{"p = { file = \"missing.png\" }", "file 'missing.png' not found"},
             Case{"p = { format = \"d32\", kind = \"3d\" }", "a 3D image cannot have a depth format"},
             Case{"p = { format = \"d32\", generator = \"checker\" }", "cannot have a depth format"},
         }) {
        Error e = invalid(with_pass("", std::string("ldr = {}\n") + c.images));
        EXPECT_TRUE(has(e.message, c.says)) << c.images << "\n" << e.format();
        EXPECT_GE(e.loc.line, 3) << c.images;
    }
    EXPECT_TRUE(valid(with_pass("", "ldr = {}\np = { file = \"tex.png\" }")));
}

TEST(Validate, NamesAreUnique) {
    Error dup = invalid(with_pass("[buffers]\nldr = { size = 16 }\n"));
    EXPECT_TRUE(has(dup.message, "the name 'ldr' is used twice")) << dup.message;
    EXPECT_EQ(dup.loc.line, 4);
    ASSERT_FALSE(dup.notes.empty());
    EXPECT_TRUE(has(dup.notes[0], "preset.toml:2"));
    Error prev = invalid(with_pass("", "ldr = {}\nacc = { history = true }\nacc_prev = {}"));
    EXPECT_TRUE(has(prev.message, "'acc_prev' is reserved for the previous frame of history resource 'acc'")) << prev.message;
    EXPECT_EQ(prev.loc.line, 4);
    Error bprev = invalid(with_pass("[buffers]\nb = { size = 4, history = true }\nb_prev = { size = 4 }\n"));
    EXPECT_TRUE(has(bprev.message, "'b_prev' is reserved")) << bprev.message;
    // The previous-frame name is free when there is no history.
    EXPECT_TRUE(valid(with_pass("", "ldr = {}\nacc = {}\nacc_prev = {}")));
}

TEST(Validate, DefaultOutput) {
    // The first colour target of the last enabled pass writing one.
    GraphDesc g = parse("[images]\na = {}\nb = {}\nc = {}\n"
                        "[[pass]]\nname = \"p1\"\nfragment = \"debug/uv.frag\"\ntargets = [\"a\"]\n"
                        "[[pass]]\nname = \"p2\"\nfragment = \"debug/uv.frag\"\ntargets = [\"b\", \"c\"]\n"
                        "[[pass]]\nname = \"p3\"\nfragment = \"debug/uv.frag\"\ntargets = [\"c\"]\nenabled = false\n");
    EXPECT_EQ(default_output(g), "b");
    ASSERT_TRUE(validate_graph(g, {}));
    EXPECT_EQ(g.output, "b");  // the non-const overload fills it in
    // A blit/copy destination counts; a resolve image replaces its multisampled target.
    EXPECT_EQ(default_output(parse("[images]\na = {}\nb = {}\n[[pass]]\nname = \"p\"\nfragment = \"debug/uv.frag\"\ntargets = [\"a\"]\n"
                                   "[[pass]]\nname = \"copy\"\nkind = \"blit\"\nsrc = \"a\"\ndst = \"b\"\n")),
              "b");
    EXPECT_EQ(default_output(parse("[images]\nm = { samples = 4 }\nr = {}\n[[pass]]\nname = \"p\"\nfragment = \"debug/uv.frag\"\n"
                                   "targets = [{ image = \"m\", resolve = \"r\" }]\n")),
              "r");
    // Compute-only: the last declared colour image.
    EXPECT_EQ(default_output(parse("[images]\na = {}\nb = {}\nd = { format = \"d32\" }\n[[pass]]\nname = \"c\"\nkind = \"compute\"\n"
                                   "compute = \"test/scale_inplace.comp\"\ngroups = 1\n")),
              "b");
    // Nothing to show is an error; an explicit buffer output too.
    Error none = invalid("[images]\nd = { format = \"d32\" }\n");
    EXPECT_TRUE(has(none.message, "no colour image to output")) << none.message;
    Error buf = invalid(with_pass("[buffers]\nb = { size = 4 }\n[output]\nimage = \"b\"\n"));
    EXPECT_TRUE(has(buf.message, "'b' is a buffer")) << buf.message;
    EXPECT_EQ(buf.loc.line, 6);
}

TEST(Validate, TestCases) {
    std::string base = with_pass("[params]\ngain = { value = 1.0, min = 0.0, max = 2.0 }\ncount = 3\non = true\ntint = [1.0, 1.0, 1.0]\n"
                                 "mode = { value = \"alpha\", options = [\"alpha\", \"beta\"] }\n");
    EXPECT_TRUE(valid(base + "[[test]]\nname = \"t\"\nset = { gain = 1.5, count = 4, on = false, tint = [0, 0, 1], mode = \"beta\" }\n"));
    struct Case {
        const char* test;
        const char* says;
        const char* hint;
    };
    for (const Case& c : {
             Case{"set = { gian = 1.0 }", "param 'gian' does not exist", "did you mean 'gain'?"},
             Case{"set = { gain = true }", "set.gain must be a number", ""},
             Case{"set = { gain = 3.0 }", "set.gain value 3 is above its max 2", ""},
             Case{"set = { count = 1.5 }", "must be an integer", ""},
             Case{"set = { on = 1 }", "must be true or false", ""},
             Case{"set = { tint = [1, 1] }", "must be 3 numbers", ""},
             Case{"set = { mode = \"gamma\" }", "is \"gamma\", not one of the options", ""},
             Case{"set = { mode = 1 }", "must be one of the options", ""},
             Case{"pass = \"lrd\"", "image 'lrd' does not exist", "did you mean 'ldr'?"},
             Case{"checks = [ { kind = \"matches_pass\", other = \"lrd\" } ]", "image 'lrd' does not exist", "did you mean 'ldr'?"},
             Case{"probes = [ { uv = [0, 0], expect = [1], pass = \"lrd\" } ]", "image 'lrd' does not exist", "did you mean 'ldr'?"},
             Case{"checks = [ { kind = \"monotone\", param = \"gian\", values = [1, 2] } ]", "param 'gian' does not exist", "did you mean 'gain'?"},
         }) {
        Error e = invalid(base + "[[test]]\nname = \"t\"\n" + c.test + "\n");
        EXPECT_TRUE(has(e.message, c.says)) << c.test << "\n" << e.format();
        EXPECT_TRUE(has(e.message, "test 't'")) << c.test;
        EXPECT_EQ(e.hint, c.hint) << c.test;
        EXPECT_EQ(e.loc.line, 16) << c.test << "\n" << e.format();
    }
}

// What a test reads must exist at the test's own size, or the case could only fail at run time
// with no location: levels, layers, probe texels and buffer elements, each at its value.
TEST(Validate, TestReadsExistAtTheTestsSize) {
    std::string base = with_pass("[buffers]\nwords = { size = 64 }\nrow = { size = \"view.w * 4\" }\nscene = { generator = \"bvh\", meshes = [\"m\"] }\n"
                                 "[meshes]\nm = { generator = \"cube\" }\n",
                                 "ldr = {}\nhiz = { format = \"r32f\", mips = \"full\" }\narr = { kind = \"2d-array\", layers = 2, size = 8 }");
    struct Case {
        const char* test;
        const char* says;
        const char* at;  // "key = value": the error points at the value
    };
    for (const Case& c : {
             Case{"checks = [ { kind = \"probe\", buffer = \"words\", index = 16, type = \"uint\", expect = 0 } ]",
                  "probe: buffer 'words'[16] is outside the buffer: 64 bytes hold 16 element(s) of 4 bytes", "index = 16"},
             Case{"checks = [ { kind = \"sum\", buffer = \"words\", range = [2, 4], stride = 16, field = 4, expect = 0 } ]",
                  "buffer 'words'[2..5] field 4 (stride 16) is outside the buffer: 64 bytes hold 4 element(s) of 16 bytes", "range = [2, 4]"},
             Case{"size = [4, 4]\nchecks = [ { kind = \"probe\", buffer = \"row\", index = 4, expect = 0 } ]",
                  "buffer 'row'[4] is outside the buffer: 16 bytes hold 4 element(s)", "index = 4"},
             Case{"size = [8, 8]\nprobes = [ { px = [0, 0], pass = \"hiz\", mip = 4, expect = [0] } ]",
                  "probe: image 'hiz' has 4 mips (0..3); mip 4 does not exist", "mip = 4"},
             Case{"pass = \"hiz\"\nmip = 10\nchecks = [ { kind = \"no_nan\" } ]", "test 't': image 'hiz' has 10 mips (0..9); mip 10 does not exist",
                  "mip = 10"},
             Case{"checks = [ { kind = \"range\", pass = \"arr\", layer = 2 } ]", "range: image 'arr' has 2 layers (0..1); layer 2 does not exist",
                  "layer = 2"},
             Case{"probes = [ { px = [320, 0], pass = \"hiz\", mip = 1, expect = [0] } ]",
                  "image 'hiz' is 320x180 at mip 1 in this test; px = [320, 0] is outside it", "px = [320, 0]"},
         }) {
        std::string text = base + "[[test]]\nname = \"t\"\n" + c.test + "\n";
        Error e = invalid(text);
        EXPECT_TRUE(has(e.message, c.says)) << c.test << "\n" << e.format();
        EXPECT_TRUE(has(e.message, "test 't'")) << c.test;
        std::string at = c.at;
        EXPECT_EQ(e.loc.line, line_of(text, at)) << c.test << "\n" << e.format();
        EXPECT_EQ(e.loc.col, col_of(text, at) + static_cast<int>(at.find('=')) + 2) << c.test << "\n" << e.format();
    }
    // Inside: the last element, the last level and texel, every layer; a host-built buffer is
    // sized by its build (left to the run); a case's own build (overridden view) skips the reads.
    EXPECT_TRUE(valid(base + "[[test]]\nname = \"t\"\nchecks = [ { kind = \"probe\", buffer = \"words\", index = 15, expect = 0 }, "
                             "{ kind = \"probe\", buffer = \"scene\", index = 100000, expect = 0 }, { kind = \"range\", pass = \"arr\", layer = 1 } ]\n"
                             "probes = [ { px = [0, 0], pass = \"hiz\", mip = 9, expect = [0] }, { px = [639, 359], expect = [0] } ]\n"));
    ValidateOptions no_reads;
    no_reads.test_reads = false;
    EXPECT_TRUE(valid(base + "[[test]]\nname = \"t\"\nchecks = [ { kind = \"probe\", buffer = \"words\", index = 16, expect = 0 } ]\n", no_reads));
}
