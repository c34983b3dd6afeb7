// The errors parsing reports: malformed TOML, a byte-order mark, unknown keys, wrong types,
// enumerated strings, out-of-range values and duplicates, each at its line and column.
#include "graph/parse.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <filesystem>

namespace fs = std::filesystem;
using namespace pl;
using namespace pl::graph;

namespace {

const fs::path kData = fs::path(PASSLAB_TEST_DIR) / "unit" / "graph" / "data";

Result<GraphDesc> parse(const std::string& text) { return parse_graph_text(text, "t/preset.toml"); }

// The error of parsing `text`, which must fail.
Error fails(const std::string& text) {
    auto g = parse(text);
    EXPECT_FALSE(g) << text;
    return g ? Error{} : g.error();
}

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

} // namespace

TEST(Parse, MalformedTomlHasLineAndColumn) {
    auto f = parse_graph_file(kData / "malformed.toml");
    ASSERT_FALSE(f);
    EXPECT_EQ(f.error().loc.line, 2);
    EXPECT_GT(f.error().loc.col, 8);
    EXPECT_TRUE(has(f.error().loc.file, "malformed.toml"));
    EXPECT_TRUE(has(f.error().message, "invalid TOML"));
    EXPECT_EQ(f.error().source_line, "title = \"unclosed");

    Error e = fails("[images]\nx = { format = \"rgba8\" }\nx = { format = \"r8\" }\n");  // duplicate key
    EXPECT_EQ(e.loc.line, 3);
    EXPECT_GT(e.loc.col, 0);
    Error m = fails("[[pass]]\nname = \"a\"\ntargets = [\"a\" \"b\"]\n");  // missing comma
    EXPECT_EQ(m.loc.line, 3);
    EXPECT_EQ(m.loc.col, 16);
    EXPECT_EQ(m.source_line, "targets = [\"a\" \"b\"]");
    EXPECT_TRUE(has(m.format(), "t/preset.toml:3:16: error: invalid TOML"));
}

TEST(Parse, BomIsAccepted) {
    auto f = parse_graph_file(kData / "bom.toml");
    ASSERT_TRUE(f) << f.error().format();
    EXPECT_EQ(f->meta.title, "bom");
    EXPECT_EQ(f->passes[0].loc.line, 8);  // lines are not shifted by the BOM
    EXPECT_EQ(f->images[0].loc.col, 1);
    Error e = fails("\xEF\xBB\xBF[preset]\ntitle = 3\n");
    EXPECT_EQ(e.loc.line, 2);
    EXPECT_EQ(e.loc.col, 9);
    Error t = fails("\xEF\xBB\xBF[preset]\ntitle = \"x\n");
    EXPECT_EQ(t.loc.line, 2);
    EXPECT_EQ(t.source_line, "title = \"x");
}

TEST(Parse, UnknownKeySuggestsTheRightKey) {
    struct Case {
        const char* text;
        const char* says;
        const char* hint;
        int line, col;
    };
    for (const Case& c : {
             Case{"[images]\nhdr = { fromat = \"rgba16f\" }\n", "image 'hdr': unknown key 'fromat'", "did you mean 'format'?", 2, 9},
             Case{"[[pass]]\nname = \"a\"\nfragmnet = \"x.frag\"\n", "unknown key 'fragmnet'", "did you mean 'fragment'?", 3, 1},
             Case{"[view]\nsize = [1, 1]\ncamrea = {}\n", "[view]: unknown key 'camrea'", "did you mean 'camera'?", 3, 1},
             Case{"[view]\ncamera = { fow = 40 }\n", "unknown key 'fow'", "did you mean 'fov'?", 2, 12},
             Case{"[images]\nx = { sampler = { adress = \"clamp\" } }\n", "unknown key 'adress'", "did you mean 'address'?", 2, 19},
             Case{"[[pass]]\nname = \"a\"\ndepth = { image = \"d\", tset = \"less\" }\n", "unknown key 'tset'", "did you mean 'test'?", 3, 24},
             Case{"[imgaes]\n", "unknown key 'imgaes'", "did you mean 'images'?", 1, 2},
             Case{"[[passes]]\nname = \"a\"\n", "unknown key 'passes'", "did you mean 'pass'?", 1, 3},
             Case{"[params]\nx = { value = 1, mn = 0 }\n", "unknown key 'mn'", "did you mean 'min'?", 2, 18},
             Case{"[meshes]\nm = { generator = \"sphere\", raduis = 1 }\n", "unknown key 'raduis'", "did you mean 'radius'?", 2, 29},
             Case{"[[test]]\nname = \"t\"\ngoldne = \"a.png\"\n", "unknown key 'goldne'", "did you mean 'golden'?", 3, 1},
             Case{"[[test]]\nname = \"t\"\nprobes = [ { uv = [0, 0], expect = [1], tols = 1 } ]\n", "unknown key 'tols'", "did you mean 'tol'?", 3, 41},
         }) {
        Error e = fails(c.text);
        EXPECT_TRUE(has(e.message, c.says)) << c.text << e.format();
        EXPECT_EQ(e.hint, c.hint) << c.text;
        EXPECT_EQ(e.loc.line, c.line) << c.text;
        EXPECT_EQ(e.loc.col, c.col) << c.text;
        ASSERT_FALSE(e.notes.empty()) << c.text;  // the valid keys are listed
        EXPECT_TRUE(has(e.notes[0], "keys: ")) << c.text;
    }
}

TEST(Parse, WrongTypesNameTheExpectedType) {
    struct Case {
        const char* text;
        const char* says;
        int line, col;
    };
    for (const Case& c : {
             Case{"[view]\nsize = \"640x360\"\n", "'size' must be an array of 2 integers, not a string", 2, 8},
             Case{"[view]\nsize = [640.5, 360]\n", "an element is a float", 2, 9},
             Case{"[view]\nsize = [640]\n", "must be an array of 2 integers, not 1", 2, 8},
             Case{"[preset]\ntags = \"a\"\n", "'tags' must be an array of strings, not a string", 2, 8},
             Case{"[images]\nx = { samples = 4.0 }\n", "'samples' must be an integer, not a float", 2, 17},
             Case{"[images]\nx = { history = 1 }\n", "'history' must be true or false, not an integer", 2, 17},
             Case{"[images]\nx = \"rgba8\"\n", "image 'x' must be a table", 2, 5},
             Case{"[images]\nx = { size = 1.5 }\n", "a size is an integer", 2, 14},
             Case{"[images]\nx = { size = [1, 2, 3, 4] }\n", "1 to 3 components", 2, 14},
             Case{"[[pass]]\nname = 3\n", "'name' must be a string, not an integer", 2, 8},
             Case{"[pass]\nname = \"a\"\n", "'pass' must be an array of tables ([[pass]]), not a table", 1, 1},
             Case{"[[pass]]\nname = \"a\"\ntargets = \"x\"\n", "'targets' must be an array", 3, 11},
             Case{"[[pass]]\nname = \"a\"\ndepth = 1\n", "'depth' must be an image name or a table", 3, 9},
             Case{"[[pass]]\nname = \"a\"\nclear = [0, 0, 0, 1]\n", "'clear' must be a table", 3, 9},
             Case{"[[pass]]\nname = \"a\"\nrepeat = [2, 2]\n", "repeat is a count", 3, 10},
             Case{"[[test]]\nname = \"t\"\nframes = \"3\"\n", "'frames' must be an integer, not a string", 3, 10},
             Case{"[[test]]\nname = \"t\"\nset = { x = { y = 1 } }\n", "must be a number, a bool, a string or an array of numbers, not a table", 3, 13},
         }) {
        Error e = fails(c.text);
        EXPECT_TRUE(has(e.message, c.says)) << c.text << e.format();
        EXPECT_EQ(e.loc.line, c.line) << c.text << e.format();
        EXPECT_EQ(e.loc.col, c.col) << c.text << e.format();
    }
}

TEST(Parse, EnumeratedStringsSuggest) {
    struct Case {
        const char* text;
        const char* hint;
    };
    for (const Case& c : {
             Case{"[[pass]]\nname = \"a\"\nkind = \"fulscreen\"\n", "did you mean \"fullscreen\"?"},
             Case{"[[pass]]\nname = \"a\"\nkind = \"draw\"\ntopology = \"triangle\"\n", "did you mean \"triangles\"?"},
             Case{"[[pass]]\nname = \"a\"\nblend = \"additiv\"\n", "did you mean \"additive\"?"},
             Case{"[[pass]]\nname = \"a\"\nblend = { src_color = \"src_alhpa\" }\n", "did you mean \"src_alpha\"?"},
             Case{"[[pass]]\nname = \"a\"\ndepth = { image = \"d\", test = \"les\" }\n", "did you mean \"less\"?"},
             Case{"[[pass]]\nname = \"a\"\nstencil = { pass = \"replase\" }\n", "did you mean \"replace\"?"},
             Case{"[images]\nx = { kind = \"cubee\" }\n", "did you mean \"cube\"?"},
             Case{"[images]\nx = { sampler = { address = [\"clamp\", \"mirorr\"] } }\n", "did you mean \"mirror\"?"},
             Case{"[images]\nx = { generator = \"checkr\" }\n", "did you mean \"checker\"?"},
             Case{"[images]\nx = { generator = \"checker\", args = { cell = 4 } }\n", "did you mean 'cells'?"},
             Case{"[meshes]\nm = { generator = \"sphre\" }\n", "did you mean \"sphere\"?"},
             Case{"[buffers]\nb = { size = 4, data = [1], type = \"flaot\" }\n", "did you mean \"float\"?"},
             Case{"[params]\nm = { value = \"blin\", options = [\"phong\", \"blinn\"] }\n", "did you mean \"blinn\"?"},
         }) {
        Error e = fails(c.text);
        EXPECT_EQ(e.hint, c.hint) << c.text << e.format();
        EXPECT_EQ(e.loc.line, std::count(c.text, c.text + std::strlen(c.text), '\n')) << c.text;
    }
}

TEST(Parse, WrongFormatSuggests) {
    Error e = fails("[images]\nhdr = { format = \"rgba16\" }\n");
    EXPECT_EQ(e.message, "image 'hdr': unknown format 'rgba16'");
    EXPECT_EQ(e.hint, "did you mean 'rgba16f'?");
    EXPECT_EQ(e.resource, "hdr");
    EXPECT_EQ(e.loc.line, 2);
    EXPECT_EQ(e.loc.col, 18);
    EXPECT_EQ(e.source_line, "");  // the text is not a file on disk; format() still shows the location
    ASSERT_FALSE(e.notes.empty());
    EXPECT_TRUE(has(e.notes[0], "d32s8"));
}

TEST(Parse, ResourceValues) {
    for (const char* text : {
             "[images]\nx = { mips = 0 }\n",
             "[images]\nx = { mips = \"all\" }\n",
             "[images]\nx = { samples = 3 }\n",
             "[images]\nx = { samples = 4, mips = 2 }\n",
             "[images]\nx = { layers = 4 }\n",
             "[images]\nx = { kind = \"2d-array\", layers = 0 }\n",
             "[images]\nx = { alias = \"y\", format = \"r8\" }\n",
             "[images]\nx = { file = \"a.png\", generator = \"checker\" }\n",
             "[images]\nx = { file = \"a.png\", size = 4 }\n",
             "[images]\nx = { args = { cells = 4 } }\n",
             "[images]\nx = { srgb = true }\n",
             "[images]\nx = { clear = [0, 0, 0] }\n",
             "[images]\nx = { sampler = { anisotropy = 100 } }\n",
             "[images]\nx = { sampler = { min_lod = 3, max_lod = 1 } }\n",
             "[images]\nuniform = {}\n",
             "[buffers]\nb = { stride = 4 }\n",
             "[buffers]\nb = { size = 4, clear = -1 }\n",
             "[buffers]\nb = { size = 4, clear = 4294967296 }\n",
             "[buffers]\nb = { size = 8, data = [1.5], type = \"int\" }\n",
             "[buffers]\nb = { size = 8, data = [-1], type = \"uint\" }\n",
             "[meshes]\nm = { instances = 2 }\n",
             "[meshes]\nm = { generator = \"cube\", file = \"a.obj\" }\n",
             "[meshes]\nm = { file = \"a.stl\" }\n",
             "[meshes]\nm = { file = \"a.obj\", radius = 1 }\n",
             "[meshes]\nm = { generator = \"cube\", size = 0 }\n",
             "[meshes]\nm = { generator = \"cube\", instances = 0 }\n",
         }) {
        Error e = fails(text);
        EXPECT_EQ(e.loc.line, 2) << text << e.format();
        EXPECT_GT(e.loc.col, 0) << text;
    }
    Error a = fails("[images]\nx = { alias = \"y\", size = 4 }\n");
    EXPECT_TRUE(has(a.message, "'size' cannot be set on an alias")) << a.message;
    EXPECT_EQ(a.loc.col, 27);
}

TEST(Parse, PassValues) {
    for (const char* text : {
             "[[pass]]\nkind = \"draw\"\n",
             "[[pass]]\nname = \"my pass\"\n",
             "[[pass]]\nname = \"a\"\nvertex = \"\"\n",
             "[[pass]]\nname = \"a\"\ntargets = [{ mip = 1 }]\n",
             "[[pass]]\nname = \"a\"\ntargets = [{ image = \"x\", layer = -3 }]\n",
             "[[pass]]\nname = \"a\"\ntargets = [{ image = \"x\", layer = \"every\" }]\n",
             "[[pass]]\nname = \"a\"\nblend = { write_mask = \"rgbx\" }\n",
             "[[pass]]\nname = \"a\"\nblend = []\n",
             "[[pass]]\nname = \"a\"\nclear = { depth = 2.0 }\n",
             "[[pass]]\nname = \"a\"\nclear = { stencil = 256 }\n",
             "[[pass]]\nname = \"a\"\nstencil = { reference = 300 }\n",
             "[[pass]]\nname = \"a\"\nindirect = { buffer = \"b\", offset = 2 }\n",
             "[[pass]]\nname = \"a\"\nindirect = { offset = 4 }\n",
             "[[pass]]\nname = \"a\"\npatch_points = 0\n",
             "[[pass]]\nname = \"a\"\nline_width = 0\n",
             "[[pass]]\nname = \"a\"\nswap = [\"a\", \"b\", \"c\"]\n",
             "[[pass]]\nname = \"a\"\ndefines = { \"A B\" = 1 }\n",
             "[[pass]]\nname = \"a\"\nbind = { x = 1 }\n",
             "[[pass]]\nname = \"a\"\ninstances = -1\n",
             "[[pass]]\nname = \"a\"\nvertex_count = 1.5\n",
             "[[test]]\nname = \"t\"\nsize = [0, 10]\n",
             "[[test]]\nname = \"t\"\nframes = 0\n",
             "[[test]]\nname = \"t\"\nstep = 0\n",
             "[[test]]\nname = \"t\"\ntolerance = { rmse = -1 }\n",
             "[[test]]\nname = \"t\"\nprobes = [ { expect = [1] } ]\n",
             "[[test]]\nname = \"t\"\nprobes = [ { uv = [0, 0], px = [0, 0], expect = [1] } ]\n",
             "[[test]]\nname = \"t\"\nprobes = [ { uv = [0, 0] } ]\n",
             "[[test]]\nname = \"t\"\nchecks = [ { min = 0 } ]\n",
             "[[test]]\nname = \"t\"\ncamera = { distance = 0 }\n",
             "[view]\ncamera = { near = 0 }\n",
             "[view]\nsize = [0, 360]\n",
             "[view]\nsize = [100000, 360]\n",
         }) {
        auto g = parse(text);
        ASSERT_FALSE(g) << text;
        EXPECT_GE(g.error().loc.line, 1) << text;
    }
    // Values as GLSL text.
    auto d = parse("[[pass]]\nname = \"a\"\ndefines = { A = 1e-7, B = -3.0, C = false, D = 1e300 }\n");
    ASSERT_TRUE(d) << d.error().format();
    EXPECT_EQ(d->passes[0].defines.at("A"), "1e-07");
    EXPECT_EQ(d->passes[0].defines.at("B"), "-3.0");
    EXPECT_EQ(d->passes[0].defines.at("C"), "0");
    EXPECT_EQ(d->passes[0].defines.at("D"), "1e+300");
    // Depth as a plain name, layers "all".
    auto l = parse("[[pass]]\nname = \"a\"\ndepth = \"d\"\ntargets = [{ image = \"x\", layer = \"all\" }]\n");
    ASSERT_TRUE(l) << l.error().format();
    EXPECT_EQ(l->passes[0].depth->target.image, "d");
    EXPECT_TRUE(l->passes[0].depth->write);
    EXPECT_EQ(l->passes[0].depth->test, "less");
    EXPECT_EQ(l->passes[0].targets[0].layer, -1);
    EXPECT_EQ(l->passes[0].keys.at("depth.image", {}).line, 3);
}

TEST(Parse, DuplicateNames) {
    Error p = fails("[[pass]]\nname = \"a\"\n[[pass]]\nname = \"a\"\n");
    EXPECT_TRUE(has(p.message, "a pass named 'a' already exists"));
    EXPECT_EQ(p.loc.line, 4);
    EXPECT_EQ(p.pass, "a");
    ASSERT_FALSE(p.notes.empty());
    EXPECT_TRUE(has(p.notes[0], "t/preset.toml:2"));
    Error t = fails("[[test]]\nname = \"a\"\n[[test]]\nname = \"a\"\n");
    EXPECT_TRUE(has(t.message, "a test named 'a' already exists"));
    EXPECT_EQ(t.loc.line, 4);
}

TEST(Parse, MissingFile) {
    auto g = parse_graph_file(kData / "does-not-exist.toml");
    ASSERT_FALSE(g);
    EXPECT_TRUE(has(g.error().message, "does-not-exist.toml"));
    EXPECT_EQ(g.error().code, ExitCode::user);
}

TEST(Parse, PassErrorsNameThePass) {
    Error e = fails("[[pass]]\nname = \"blur\"\ncull = \"both\"\n");
    EXPECT_EQ(e.pass, "blur");
    EXPECT_TRUE(has(e.format(), "[pass 'blur']"));
}

TEST(Parse, MipAndLayerSelectionsAndGroups) {
    auto g = parse(R"(
[[pass]]
name = "reduce"
fragment = "r.frag"
targets = [{ image = "hiz", mip = "iteration + 1" }, { image = "arr", layer = "iteration / 2" }]
bind = { src = { image = "hiz", mip = "iteration" }, one = { image = "arr", layer = 3 } }

[[group]]
name = "peel"
repeat = "params.n"
passes = ["reduce"]
swap = ["a", "b"]
)");
    ASSERT_TRUE(g) << g.error().format();
    const PassDesc& p = g->passes[0];
    EXPECT_EQ(p.targets[0].mip_expr.text, "iteration + 1");
    EXPECT_EQ(p.targets[1].layer_expr.text, "iteration / 2");
    EXPECT_EQ(p.bind.at("src"), "hiz");  // a view also renames
    EXPECT_EQ(p.bind_views.at("src").mip.text, "iteration");
    EXPECT_EQ(p.bind_views.at("one").layer.literal, (std::vector<int64_t>{3}));
    ASSERT_EQ(g->groups.size(), 1u);
    EXPECT_EQ(g->groups[0].passes, (std::vector<std::string>{"reduce"}));
    EXPECT_EQ(g->group_of("reduce"), &g->groups[0]);
    EXPECT_EQ(g->groups[0].keys.at("passes.0", {}).line, 11);
}

TEST(Parse, ViewsAndGroupsAreStrict) {
    auto none = fails("[[pass]]\nname = \"p\"\nfragment = \"f\"\nbind = { src = { image = \"hiz\" } }\n");
    EXPECT_TRUE(has(none.message, "selects nothing"));
    auto key = fails("[[pass]]\nname = \"p\"\nfragment = \"f\"\nbind = { src = { image = \"hiz\", lod = 1 } }\n");
    EXPECT_TRUE(has(key.message, "unknown key 'lod'"));
    auto empty = fails("[[group]]\nname = \"g\"\nrepeat = 2\n");
    EXPECT_TRUE(has(empty.message, "needs passes"));
    auto odd = fails("[[group]]\nname = \"g\"\npasses = [\"a\"]\nswap = [\"a\"]\n");
    EXPECT_TRUE(has(odd.message, "even number"));
    auto twice = fails("[[group]]\nname = \"g\"\npasses = [\"a\"]\n[[group]]\nname = \"g\"\npasses = [\"b\"]\n");
    EXPECT_TRUE(has(twice.message, "already exists"));
    EXPECT_EQ(twice.loc.line, 5);
}
