// preset.toml parsing and validation: values and their locations, and the errors users see.
#include "graph/parse.hpp"
#include "graph/validate.hpp"
#include "graph/dot.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace pl;
using namespace pl::graph;

namespace {

Result<GraphDesc> parse(const std::string& text) { return parse_graph_text(text, "t/preset.toml"); }

Status validate(GraphDesc& g) {
    ValidateOptions o;
    o.search_dirs = {fs::path(PASSLAB_SOURCE_DIR) / "passes"};
    return validate_graph(g, o);
}

const char* kFull = R"([preset]
title = "Full"
family = "tests"
summary = "every section"
tags = ["a", "b"]

[view]
size = [320, 200]
camera = { orbit = { target = [0, 1, 0], distance = 4.0, yaw = 10, pitch = -5 }, fov = 60, near = 0.1, far = 50 }

[params]
gain = { value = 1.5, min = 0.0, max = 4.0, log = true, doc = "gain" }
count = 3
on = true
offset = [0.5, 0.25]
tint = { value = [1.0, 0.5, 0.25], color = true }
mode = { value = "b", options = ["a", "b", "c"] }

[images]
hdr = { format = "rgba16f", size = "view/2", sampler = { filter = "nearest", address = ["clamp", "mirror"], anisotropy = 8 } }
depth = { format = "d32s8" }
env = { kind = "cube", size = 64, format = "rgba16f", mips = "full" }
vol = { kind = "3d", size = [16, 16, 8], format = "r32f" }
acc = { format = "rgba32f", history = true, clear = [0, 0, 0, 1] }
grid = { generator = "checker", args = { cells = [4] }, srgb = true }
view2 = { alias = "hdr", sampler = { compare = "less" } }

[buffers]
nodes = { size = "view.w * view.h * 4", stride = 16, clear = 0 }
seed = { size = 16, data = [1, 2, 3, 4], type = "uint" }

[meshes]
ball = { generator = "sphere", radius = 0.5, segments = 32, instances = 4 }

[[pass]]
name = "shade"
kind = "draw"
mesh = "ball"
vertex = "debug/uv.frag"
fragment = "debug/uv.frag"
targets = ["hdr", { image = "env", layer = "iteration", mip = 0 }]
depth = { image = "depth", test = "less_equal", write = false, bias_constant = 1.5 }
stencil = { reference = 1, pass = "replace", compare = "always", back = { fail = "zero" } }
blend = ["additive", { src_color = "src_alpha", dst_color = "one_minus_src_alpha", alpha_op = "max" }]
clear = { color = [0, 0, 0, 1], depth = 1.0, stencil = 0 }
repeat = 6
defines = { FAST = 1, NAME = "x" }
bind = { input = "grid" }
cull = "none"

[[pass]]
name = "reduce"
kind = "compute"
compute = "debug/uv.frag"
threads = "view"
swap = ["hdr", "acc"]

[output]
image = "hdr"

[[test]]
name = "t1"
size = [64, 32]
time = 0.5
frames = 3
set = { gain = 2.0, mode = "c" }
golden = "snapshots/t1.png"
tolerance = { rmse = 0.01 }
probes = [ { uv = [0.5, 0.5], expect = [1, 0, 0], tol = 0.01 } ]
checks = [ { kind = "range", min = 0, max = 1, channel = 0 } ]
requires = ["geometry_shader"]
)";

} // namespace

TEST(Parse, EverySection) {
    auto g = parse(kFull);
    ASSERT_TRUE(g) << g.error().format();
    EXPECT_EQ(g->meta.title, "Full");
    EXPECT_EQ(g->meta.tags.size(), 2u);
    EXPECT_EQ(g->view.size[0], 320);
    EXPECT_FLOAT_EQ(g->view.orbit.distance, 4.0f);
    EXPECT_FLOAT_EQ(g->view.fov, 60.0f);
    ASSERT_EQ(g->params.size(), 6u);
    EXPECT_EQ(g->params[0].type, ParamType::f32);
    EXPECT_TRUE(g->params[0].log);
    EXPECT_EQ(g->params[1].type, ParamType::i32);
    EXPECT_EQ(g->params[2].type, ParamType::boolean);
    EXPECT_EQ(g->params[3].type, ParamType::vec2);
    EXPECT_EQ(g->params[4].type, ParamType::color3);
    EXPECT_EQ(g->params[5].type, ParamType::enumeration);
    EXPECT_EQ(g->params[5].value[0], 1.0);
    const ImageDesc* hdr = g->find_image("hdr");
    ASSERT_TRUE(hdr);
    EXPECT_EQ(hdr->size.text, "view/2");
    EXPECT_EQ(hdr->sampler.filter, "nearest");
    EXPECT_EQ(hdr->sampler.address[1], "mirror");
    EXPECT_EQ(hdr->sampler.address[2], "mirror");
    EXPECT_EQ(g->find_image("env")->kind, ImageKind::cube);
    EXPECT_EQ(g->find_image("env")->mips, 0);
    EXPECT_EQ(g->find_image("vol")->size.literal.size(), 3u);
    EXPECT_TRUE(g->find_image("acc")->history);
    EXPECT_EQ(g->find_image("grid")->generator_args.at("cells")[0], 4.0);
    EXPECT_EQ(g->find_image("view2")->alias, "hdr");
    EXPECT_EQ(*g->find_buffer("nodes")->clear, 0u);
    EXPECT_EQ(g->find_buffer("seed")->data.size(), 4u);
    EXPECT_EQ(g->find_mesh("ball")->instances, 4);
    EXPECT_EQ(g->find_mesh("ball")->args.at("segments"), 32.0);
    const PassDesc* p = g->find_pass("shade");
    ASSERT_TRUE(p);
    EXPECT_EQ(p->kind, PassKind::draw);
    EXPECT_EQ(p->targets.size(), 2u);
    EXPECT_EQ(p->targets[1].layer, -2);
    EXPECT_EQ(p->depth->test, "less_equal");
    EXPECT_FALSE(p->depth->write);
    EXPECT_TRUE(p->stencil.enable);
    EXPECT_EQ(p->stencil.front.pass, "replace");
    EXPECT_EQ(p->stencil.back.fail, "zero");
    EXPECT_EQ(p->stencil.back.pass, "replace");
    ASSERT_EQ(p->blend.size(), 2u);
    EXPECT_EQ(p->blend[0].dst_color, "one");
    EXPECT_EQ(p->blend[1].alpha_op, "max");
    EXPECT_EQ(*p->clear.stencil, 0u);
    EXPECT_EQ(p->defines.at("FAST"), "1");
    EXPECT_EQ(p->bind.at("input"), "grid");
    EXPECT_EQ(p->loc.line, 36);
    EXPECT_EQ(g->passes[1].swap.size(), 2u);
    ASSERT_EQ(g->tests.size(), 1u);
    EXPECT_EQ(g->tests[0].frames, 3);
    EXPECT_EQ(g->tests[0].checks.size(), 2u);
    EXPECT_EQ(g->tests[0].checks[0].kind, "probe");
    EXPECT_EQ(g->tests[0].checks[1].kind, "range");
    EXPECT_EQ(g->tests[0].requires_features[0], "geometry_shader");
    EXPECT_NE(to_dot(*g, nullptr).find("\"pass:shade\" -> \"hdr\""), std::string::npos);
}

TEST(Parse, MalformedTomlHasLineAndColumn) {
    auto g = parse("[preset]\ntitle = \"unclosed\n[view]\n");
    ASSERT_FALSE(g);
    EXPECT_EQ(g.error().loc.line, 2);
    EXPECT_GT(g.error().loc.col, 0);
    EXPECT_NE(g.error().message.find("invalid TOML"), std::string::npos);
    EXPECT_EQ(g.error().source_line, "title = \"unclosed");
}

TEST(Parse, UnknownKeySuggests) {
    auto g = parse("[images]\nhdr = { fromat = \"rgba16f\" }\n");
    ASSERT_FALSE(g);
    EXPECT_NE(g.error().message.find("unknown key 'fromat'"), std::string::npos);
    EXPECT_EQ(g.error().hint, "did you mean 'format'?");
    EXPECT_EQ(g.error().loc.line, 2);
    EXPECT_EQ(g.error().loc.col, 9);
}

TEST(Parse, BomIsAccepted) {
    auto g = parse("\xEF\xBB\xBF[preset]\ntitle = \"bom\"\n");
    ASSERT_TRUE(g) << g.error().format();
    EXPECT_EQ(g->meta.title, "bom");
}

TEST(Validate, UnknownTargetSuggestsAndNamesPass) {
    auto g = parse("[images]\nalbedo = { format = \"rgba8\" }\n\n[[pass]]\nname = \"p\"\nfragment = \"debug/uv.frag\"\ntargets = [\"albdo\"]\n");
    ASSERT_TRUE(g);
    auto s = validate(*g);
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().pass, "p");
    EXPECT_EQ(s.error().loc.line, 7);
    EXPECT_EQ(s.error().hint, "did you mean 'albedo'?");
}

TEST(Validate, WrongFormatSuggests) {
    auto g = parse("[images]\nhdr = { format = \"rgba16\" }\n");
    ASSERT_TRUE(g);
    auto s = validate(*g);
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().hint, "did you mean 'rgba16f'?");
    EXPECT_EQ(s.error().loc.line, 2);
}

TEST(Validate, SizesAreCheckedBeforeAllocation) {
    for (const char* size : {"[0, 360]", "[-5, 5]", "[100000, 100000]", "\"view - view\""}) {
        auto g = parse(std::string("[images]\nbig = { format = \"rgba8\", size = ") + size + " }\n");
        ASSERT_TRUE(g) << size;
        auto s = validate(*g);
        ASSERT_FALSE(s) << size;
        EXPECT_EQ(s.error().loc.line, 2) << size;
        EXPECT_EQ(s.error().resource, "big");
        EXPECT_NE(s.error().message.find("size evaluates to"), std::string::npos) << s.error().message;
    }
    auto mem = parse("[images]\nbig = { format = \"rgba32f\", size = [16384, 16384] }\n");
    auto s = validate(*mem);
    ASSERT_FALSE(s);
    EXPECT_NE(s.error().message.find("4.0 GiB"), std::string::npos) << s.error().message;
    auto buf = parse("[buffers]\nb = { size = \"view.w * view.h * 100000\" }\n");
    auto sb = validate(*buf);
    ASSERT_FALSE(sb);
    EXPECT_NE(sb.error().message.find("buffer 'b'"), std::string::npos);
}

TEST(Validate, DuplicateNamesAndMissingShader) {
    auto dup = parse("[images]\nx = { format = \"rgba8\" }\n[buffers]\nx = { size = 16 }\n");
    EXPECT_FALSE(validate(*dup));
    auto p = parse("[images]\nx = { format = \"rgba8\" }\n[[pass]]\nname = \"a\"\nfragment = \"nope.frag\"\ntargets = [\"x\"]\n");
    auto s = validate(*p);
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().loc.line, 5);
    EXPECT_NE(s.error().message.find("nope.frag"), std::string::npos);
    auto twice = parse("[[pass]]\nname = \"a\"\nfragment = \"debug/uv.frag\"\n[[pass]]\nname = \"a\"\nfragment = \"debug/uv.frag\"\n");
    ASSERT_FALSE(twice);
    EXPECT_EQ(twice.error().loc.line, 5);
}

TEST(Validate, DefaultOutputIsLastTarget) {
    auto g = parse("[images]\na = { format = \"rgba8\" }\nb = { format = \"rgba8\" }\n"
                   "[[pass]]\nname = \"p1\"\nfragment = \"debug/uv.frag\"\ntargets = [\"a\"]\n"
                   "[[pass]]\nname = \"p2\"\nfragment = \"debug/uv.frag\"\ntargets = [\"b\"]\n");
    ASSERT_TRUE(validate(*g));
    EXPECT_EQ(g->output, "b");
}
