// preset.toml -> GraphDesc: every key of data/full.toml with its value and source location, the
// defaults of what is not written, and how params get their types (parse_errors_test.cpp has the
// errors).
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

TEST(Parse, EveryKey) {
    auto r = parse_graph_file(kData / "full.toml");
    ASSERT_TRUE(r) << r.error().format();
    const GraphDesc& g = *r;
    EXPECT_EQ(g.file, fs::absolute(kData / "full.toml"));
    EXPECT_EQ(g.dir, fs::absolute(kData));

    // [preset]
    EXPECT_EQ(g.meta.title, "Every key");
    EXPECT_EQ(g.meta.family, "tests");
    EXPECT_EQ(g.meta.summary, "exercises every key of the format");
    EXPECT_EQ(g.meta.tags, (std::vector<std::string>{"a", "b"}));

    // [view]
    EXPECT_EQ(g.view.size, (std::array<int, 2>{320, 200}));
    EXPECT_EQ(g.view.orbit.target, (std::array<float, 3>{0, 1, 0}));
    EXPECT_FLOAT_EQ(g.view.orbit.distance, 4.0f);
    EXPECT_FLOAT_EQ(g.view.orbit.yaw, 10.0f);
    EXPECT_FLOAT_EQ(g.view.orbit.pitch, -5.0f);
    EXPECT_FLOAT_EQ(g.view.fov, 60.0f);
    EXPECT_FLOAT_EQ(g.view.near, 0.1f);
    EXPECT_FLOAT_EQ(g.view.far, 50.0f);
    EXPECT_TRUE(g.view.ortho);
    EXPECT_FLOAT_EQ(g.view.ortho_height, 3.5f);

    // [params], in declaration order.
    std::vector<std::string> order;
    for (const auto& p : g.params) order.push_back(p.name);
    EXPECT_EQ(order, (std::vector<std::string>{"gain", "count", "on", "offset", "dir", "quat", "tint", "tint4", "mode", "taps", "scale"}));
    const ParamDesc* gain = g.find_param("gain");
    ASSERT_TRUE(gain);
    EXPECT_EQ(gain->type, ParamType::f32);
    EXPECT_EQ(gain->value[0], 1.5);
    EXPECT_EQ(*gain->min, 0.0);
    EXPECT_EQ(*gain->max, 4.0);
    EXPECT_TRUE(gain->log);
    EXPECT_EQ(gain->doc, "gain");
    EXPECT_EQ(gain->loc.line, 14);
    EXPECT_EQ(gain->loc.col, 1);
    EXPECT_EQ(gain->keys.at("value", {}).col, 18);
    EXPECT_EQ(g.find_param("count")->type, ParamType::i32);
    EXPECT_EQ(g.find_param("count")->value[0], 3.0);
    EXPECT_EQ(g.find_param("on")->type, ParamType::boolean);
    EXPECT_EQ(g.find_param("on")->value[0], 1.0);
    EXPECT_EQ(g.find_param("offset")->type, ParamType::vec2);
    EXPECT_EQ(g.find_param("offset")->value[1], 0.25);
    EXPECT_EQ(g.find_param("dir")->type, ParamType::vec3);
    EXPECT_EQ(g.find_param("quat")->type, ParamType::vec4);
    EXPECT_EQ(g.find_param("quat")->components(), 4);
    EXPECT_EQ(g.find_param("tint")->type, ParamType::color3);
    EXPECT_EQ(g.find_param("tint4")->type, ParamType::color4);
    const ParamDesc* mode = g.find_param("mode");
    EXPECT_EQ(mode->type, ParamType::enumeration);
    EXPECT_EQ(mode->options, (std::vector<std::string>{"a", "b", "c"}));
    EXPECT_EQ(mode->value[0], 1.0);
    EXPECT_EQ(mode->components(), 1);
    EXPECT_EQ(g.find_param("taps")->type, ParamType::i32);
    EXPECT_EQ(g.find_param("taps")->value[0], 4.0);
    EXPECT_EQ(g.find_param("scale")->type, ParamType::f32);
    EXPECT_EQ(g.find_param("scale")->value[0], 2.0);

    // [images], in declaration order.
    ASSERT_EQ(g.images.size(), 11u);
    EXPECT_EQ(g.images.front().name, "hdr");
    EXPECT_EQ(g.images.back().name, "ldr");
    const ImageDesc* hdr = g.find_image("hdr");
    EXPECT_EQ(hdr->kind, ImageKind::tex2d);
    EXPECT_EQ(hdr->format, "rgba16f");
    EXPECT_EQ(hdr->format_loc.line, 27);
    EXPECT_EQ(hdr->format_loc.col, 18);
    EXPECT_EQ(hdr->size.text, "view/2");
    EXPECT_EQ(hdr->size.loc.line, 27);
    EXPECT_EQ(hdr->size.loc.col, 36);
    EXPECT_EQ(hdr->sampler.filter, "nearest");
    EXPECT_EQ(hdr->sampler.mip_filter, "nearest");
    EXPECT_EQ(hdr->sampler.address, (std::array<std::string, 3>{"clamp", "mirror", "mirror"}));
    EXPECT_EQ(hdr->sampler.border, "opaque_white");
    EXPECT_FLOAT_EQ(hdr->sampler.anisotropy, 8);
    EXPECT_FLOAT_EQ(hdr->sampler.lod_bias, 0.5f);
    EXPECT_FLOAT_EQ(hdr->sampler.min_lod, 1);
    EXPECT_FLOAT_EQ(hdr->sampler.max_lod, 4);
    EXPECT_EQ(hdr->sampler.compare, "");
    const ImageDesc* env = g.find_image("env");
    EXPECT_EQ(env->kind, ImageKind::cube);
    EXPECT_EQ(env->mips, 0);  // "full"
    EXPECT_EQ(env->size.literal, (std::vector<int64_t>{64}));
    EXPECT_EQ(g.find_image("arr")->kind, ImageKind::tex2d_array);
    EXPECT_EQ(g.find_image("arr")->layers, 4);
    EXPECT_EQ(g.find_image("arr")->mips, 3);
    EXPECT_EQ(g.find_image("vol")->kind, ImageKind::tex3d);
    EXPECT_EQ(g.find_image("vol")->size.literal, (std::vector<int64_t>{16, 16, 8}));
    const ImageDesc* acc = g.find_image("acc");
    EXPECT_TRUE(acc->history);
    EXPECT_EQ(*acc->clear, (std::array<double, 4>{0, 0, 0, 1}));
    const ImageDesc* grid = g.find_image("grid");
    EXPECT_EQ(grid->generator, "checker");
    EXPECT_TRUE(grid->srgb);
    EXPECT_TRUE(grid->size.empty());  // generators default to 256x256 at evaluation
    EXPECT_EQ(grid->generator_args.at("cells"), (std::vector<double>{4}));
    EXPECT_EQ(grid->generator_args.at("color_a"), (std::vector<double>{1, 0, 0, 1}));
    const ImageDesc* photo = g.find_image("photo");
    EXPECT_EQ(photo->file, "tex.png");
    EXPECT_FALSE(photo->format_loc.known());  // not written: the file decides
    EXPECT_EQ(photo->sampler.address[2], "border");
    EXPECT_EQ(photo->sampler.compare, "less");
    EXPECT_EQ(g.find_image("shadowmap")->alias, "depth");
    EXPECT_EQ(g.find_image("shadowmap")->sampler.compare, "less_equal");
    EXPECT_EQ(g.find_image("msaa")->samples, 4);
    EXPECT_EQ(g.find_image("ldr")->format, "rgba8");  // the default
    EXPECT_EQ(g.find_image("ldr")->keys.at("size", {}).line, 37);

    // [buffers]
    const BufferDesc* nodes = g.find_buffer("nodes");
    EXPECT_EQ(nodes->size.text, "view.w * view.h * 4");
    EXPECT_EQ(nodes->stride, 16);
    EXPECT_EQ(*nodes->clear, 4294967295u);
    EXPECT_EQ(nodes->loc.line, 40);
    EXPECT_EQ(g.find_buffer("seed")->size.literal, (std::vector<int64_t>{16}));
    EXPECT_EQ(g.find_buffer("seed")->data, (std::vector<double>{1, 2, 3, 4}));
    EXPECT_EQ(g.find_buffer("seed")->data_type, "uint");
    EXPECT_TRUE(g.find_buffer("args")->history);
    EXPECT_EQ(g.find_buffer("nodes")->data_type, "float");

    // [meshes]
    const MeshDesc* ball = g.find_mesh("ball");
    EXPECT_EQ(ball->generator, "sphere");
    EXPECT_EQ(ball->instances, 4);
    EXPECT_EQ(ball->args, (std::map<std::string, double>{{"radius", 0.5}, {"rings", 16}, {"segments", 32}}));
    EXPECT_EQ(g.find_mesh("ring")->args.at("tube"), 0.2);
    EXPECT_EQ(g.find_mesh("pot")->args.at("subdivisions"), 4);
    EXPECT_EQ(g.find_mesh("model")->file, "model.obj");
    EXPECT_EQ(g.find_mesh("model")->instances, 1);

    // [[pass]] shade: a draw pass with every raster key.
    ASSERT_EQ(g.passes.size(), 8u);
    const PassDesc& p = g.passes[0];
    EXPECT_EQ(p.name, "shade");
    EXPECT_EQ(p.loc.line, 51);
    EXPECT_EQ(p.kind, PassKind::draw);
    EXPECT_EQ(p.mesh, "ball");
    EXPECT_EQ(p.keys.at("mesh", {}).line, 53);
    EXPECT_EQ(p.keys.at("mesh", {}).col, 8);
    EXPECT_EQ(p.vertex.file, "test/quad.vert");
    EXPECT_EQ(p.vertex.loc.line, 54);
    EXPECT_EQ(p.vertex.loc.col, 10);
    EXPECT_EQ(p.tess_control.file, "local.tesc");
    EXPECT_EQ(p.tess_eval.file, "local.tese");
    EXPECT_EQ(p.geometry.file, "local.geom");
    EXPECT_EQ(p.fragment.file, "debug/uv.frag");
    EXPECT_TRUE(p.compute.empty());
    EXPECT_EQ(p.topology, "patches");
    EXPECT_EQ(p.patch_points, 4);
    ASSERT_EQ(p.targets.size(), 2u);
    EXPECT_EQ(p.targets[0].image, "msaa");
    EXPECT_EQ(p.targets[0].resolve, "hdr");
    EXPECT_EQ(p.targets[0].loc.line, 61);
    EXPECT_EQ(p.targets[1].image, "env");
    EXPECT_EQ(p.targets[1].layer, -2);  // "iteration"
    EXPECT_EQ(p.targets[1].mip, 0);
    ASSERT_TRUE(p.depth);
    EXPECT_EQ(p.depth->target.image, "depth");
    EXPECT_EQ(p.depth->test, "less_equal");
    EXPECT_FALSE(p.depth->write);
    EXPECT_FLOAT_EQ(p.depth->bias_constant, 1.5f);
    EXPECT_FLOAT_EQ(p.depth->bias_slope, 2.0f);
    EXPECT_TRUE(p.depth->clamp);
    EXPECT_EQ(p.depth->target.layer, 0);
    EXPECT_EQ(p.keys.at("depth.image", {}).line, 62);
    EXPECT_TRUE(p.stencil.enable);
    EXPECT_EQ(p.stencil.reference, 1u);
    EXPECT_EQ(p.stencil.read_mask, 15u);
    EXPECT_EQ(p.stencil.write_mask, 240u);
    EXPECT_EQ(p.stencil.front.pass, "replace");     // flat keys apply to both faces
    EXPECT_EQ(p.stencil.front.compare, "equal");    // ... front overrides its compare
    EXPECT_EQ(p.stencil.back.compare, "always");
    EXPECT_EQ(p.stencil.back.pass, "replace");
    EXPECT_EQ(p.stencil.back.fail, "zero");
    EXPECT_EQ(p.stencil.back.depth_fail, "invert");
    EXPECT_EQ(p.stencil.front.fail, "keep");
    ASSERT_EQ(p.blend.size(), 2u);
    EXPECT_TRUE(p.blend[0].enable);
    EXPECT_EQ(p.blend[0].src_color, "one");
    EXPECT_EQ(p.blend[0].dst_color, "one");
    EXPECT_EQ(p.blend[1].src_color, "src_alpha");
    EXPECT_EQ(p.blend[1].dst_color, "one_minus_src_alpha");
    EXPECT_EQ(p.blend[1].dst_alpha, "zero");
    EXPECT_EQ(p.blend[1].alpha_op, "max");
    EXPECT_EQ(p.blend[1].write_mask, "rgb");
    EXPECT_EQ(*p.clear.color, (std::array<double, 4>{0, 0, 0, 1}));
    EXPECT_EQ(*p.clear.depth, 1.0f);
    EXPECT_EQ(*p.clear.stencil, 7u);
    EXPECT_EQ(p.repeat.literal, (std::vector<int64_t>{6}));
    EXPECT_EQ(p.defines, (std::map<std::string, std::string>{{"FAST", "1"}, {"NAME", "x"}, {"ON", "1"}, {"K", "0.5"}, {"TWO", "2.0"}}));
    EXPECT_EQ(p.bind.at("input"), "grid");
    EXPECT_EQ(p.bind_loc.line, 68);
    EXPECT_EQ(p.cull, "none");
    EXPECT_EQ(p.front_face, "cw");
    EXPECT_EQ(p.polygon, "line");
    EXPECT_FLOAT_EQ(p.line_width, 2.0f);
    EXPECT_EQ(*p.instances, 2);
    EXPECT_EQ(p.indirect, "args");
    EXPECT_EQ(p.indirect_offset, 4u);
    EXPECT_EQ(p.keys.at("indirect", {}).line, 74);
    EXPECT_TRUE(p.enabled);

    // compute, fullscreen, blit, mips, clear, copy.
    const PassDesc* sim = g.find_pass("sim");
    EXPECT_EQ(sim->kind, PassKind::compute);
    EXPECT_EQ(sim->compute.file, "test/scale_inplace.comp");
    EXPECT_EQ(sim->threads.text, "view");
    EXPECT_TRUE(sim->groups.empty());
    EXPECT_EQ(sim->swap, (std::vector<std::string>{"hdr", "acc"}));
    EXPECT_EQ(sim->repeat.text, "params.taps");
    EXPECT_EQ(sim->repeat.loc.line, 83);
    EXPECT_EQ(g.find_pass("sim2")->groups.text, "ceil_div(view, 8)");
    EXPECT_EQ(g.find_pass("sim2")->indirect, "args");
    const PassDesc* post = g.find_pass("post");
    EXPECT_EQ(post->kind, PassKind::fullscreen);  // the default kind
    EXPECT_EQ(post->blend[0].src_color, "src_alpha");
    EXPECT_EQ(post->blend[0].dst_color, "one_minus_src_alpha");
    EXPECT_FALSE(post->clear.depth);  // absent: loaded
    const PassDesc* down = g.find_pass("down");
    EXPECT_EQ(down->kind, PassKind::blit);
    EXPECT_EQ(down->src, "hdr");
    EXPECT_EQ(down->dst, "acc");
    EXPECT_EQ(down->filter, "nearest");
    EXPECT_EQ(g.find_pass("gen_mips")->kind, PassKind::mips);
    EXPECT_EQ(g.find_pass("gen_mips")->image, "env");
    EXPECT_EQ(g.find_pass("wipe")->kind, PassKind::clear);
    EXPECT_EQ(g.find_pass("dup")->kind, PassKind::copy);
    EXPECT_FALSE(g.find_pass("dup")->enabled);

    // [output]
    EXPECT_EQ(g.output, "ldr");
    EXPECT_EQ(g.output_loc.line, 126);

    // [[test]]
    ASSERT_EQ(g.tests.size(), 2u);
    const TestDesc& t = g.tests[0];
    EXPECT_EQ(t.name, "t1");
    EXPECT_EQ(t.loc.line, 129);
    EXPECT_EQ(*t.size, (std::array<int, 2>{64, 32}));
    EXPECT_EQ(t.time, 0.5);
    EXPECT_EQ(t.frames, 3);
    EXPECT_EQ(t.step, 0.02);
    EXPECT_EQ(std::get<double>(t.set.at("gain")), 2.0);
    EXPECT_EQ(std::get<std::string>(t.set.at("mode")), "c");
    EXPECT_EQ(std::get<bool>(t.set.at("on")), false);
    EXPECT_EQ(std::get<std::vector<double>>(t.set.at("offset")), (std::vector<double>{0.1, 0.2}));
    EXPECT_EQ(t.keys.at("set.count", {}).line, 134);
    ASSERT_TRUE(t.camera);
    EXPECT_EQ(t.camera->target, (std::array<float, 3>{1, 2, 3}));
    EXPECT_FLOAT_EQ(t.camera->distance, 5);
    EXPECT_FLOAT_EQ(t.camera->yaw, 45);
    EXPECT_FLOAT_EQ(t.camera->pitch, 30);
    EXPECT_EQ(t.pass, "hdr");
    EXPECT_EQ(t.golden, "snapshots/t1.png");
    EXPECT_EQ(t.tolerance.size(), 5u);
    EXPECT_EQ(t.tolerance.at("ssim"), 0.98);
    ASSERT_EQ(t.checks.size(), 5u);
    EXPECT_EQ(t.checks[0].kind, "probe");
    EXPECT_EQ(std::get<std::vector<double>>(t.checks[0].args.at("uv")), (std::vector<double>{0.5, 0.5}));
    EXPECT_EQ(std::get<double>(t.checks[0].args.at("tol")), 0.01);
    EXPECT_EQ(t.checks[1].kind, "probe");
    EXPECT_EQ(std::get<std::string>(t.checks[1].args.at("pass")), "ldr");
    EXPECT_EQ(t.checks[2].kind, "range");
    EXPECT_EQ(std::get<double>(t.checks[2].args.at("max")), 1.0);
    EXPECT_EQ(t.checks[2].args.count("kind"), 0u);
    EXPECT_EQ(t.checks[3].kind, "matches_pass");
    EXPECT_EQ(t.checks[4].kind, "monotone");
    EXPECT_EQ(t.checks[4].loc.line, 140);
    EXPECT_EQ(t.requires_features, (std::vector<std::string>{"geometry_shader", "tessellation_shader"}));
    const TestDesc& d = g.tests[1];  // defaults
    EXPECT_FALSE(d.size);
    EXPECT_EQ(d.time, 0.0);
    EXPECT_EQ(d.frames, 1);
    EXPECT_DOUBLE_EQ(d.step, 1.0 / 60.0);
    EXPECT_FALSE(d.camera);
    EXPECT_TRUE(d.checks.empty());
}

TEST(Parse, Defaults) {
    auto g = parse("");
    ASSERT_TRUE(g) << g.error().format();
    EXPECT_EQ(g->view.size, (std::array<int, 2>{640, 360}));
    EXPECT_FLOAT_EQ(g->view.fov, 45);
    auto i = parse("[images]\nx = {}\n[[pass]]\nname = \"p\"\n");
    ASSERT_TRUE(i) << i.error().format();
    const ImageDesc& x = i->images[0];
    EXPECT_EQ(x.format, "rgba8");
    EXPECT_TRUE(x.size.empty());  // "view" at evaluation
    EXPECT_EQ(x.mips, 1);
    EXPECT_EQ(x.samples, 1);
    EXPECT_EQ(x.sampler.filter, "linear");
    EXPECT_EQ(x.sampler.address[0], "repeat");
    const PassDesc& p = i->passes[0];
    EXPECT_EQ(p.kind, PassKind::fullscreen);
    EXPECT_TRUE(p.blend.empty());
    EXPECT_FALSE(p.clear.color);
    EXPECT_EQ(p.cull, "back");
    EXPECT_EQ(p.topology, "triangles");
    EXPECT_TRUE(p.enabled);
}

TEST(Parse, Params) {
    auto g = parse("[params]\nz = 1\ny = 2.0\nx = { value = 1, type = \"float\" }\n");
    ASSERT_TRUE(g) << g.error().format();
    EXPECT_EQ(g->params[0].name, "z");  // declaration order, not key order
    EXPECT_EQ(g->params[2].type, ParamType::f32);
    struct Case {
        const char* text;
        const char* says;
        int col;
    };
    for (const Case& c : {
             Case{"[params]\nx = { value = 5, min = 0, max = 2 }\n", "param 'x': value 5 is above its max 2", 15},
             Case{"[params]\nx = { value = [0.5, -1], min = 0 }\n", "value -1 is below its min 0", 15},
             Case{"[params]\nx = { value = 1, min = 3, max = 2 }\n", "min 3 is greater than max 2", 33},
             Case{"[params]\nx = { value = 1.5, type = \"int\" }\n", "declared int but the value 1.5 is not a 32-bit integer", 15},
             Case{"[params]\nx = { value = 1, type = \"bool\" }\n", "declared bool but the value is an integer", 15},
             Case{"[params]\nx = { value = [1, 2], type = \"vec3\" }\n", "declared vec3 but the value is an array of 2", 15},
             Case{"[params]\nx = { value = [1, 2], color = true }\n", "color = true needs 3 or 4 numbers", 15},
             Case{"[params]\nx = { value = \"a\" }\n", "needs options", 15},
             Case{"[params]\nx = { value = 1, options = [\"a\"] }\n", "options = [...] make an enum", 15},
             Case{"[params]\nx = { value = \"a\", options = [\"a\", \"b c\"] }\n", "must be an identifier", 30},
             Case{"[params]\nx = { min = 1 }\n", "needs value", 1},
             Case{"[params]\nx = [1, 2, 3, 4, 5]\n", "2 to 4 numbers, not 5", 5},
             Case{"[params]\nx = [1, \"a\"]\n", "an element is a string", 5},
             Case{"[params]\nx = { value = true, min = 0 }\n", "min/max apply to numbers", 27},
             Case{"[params]\nx = { value = [1, 2], log = true }\n", "log = true applies to a float or int", 29},
             Case{"[params]\nuniform = 1\n", "GLSL keyword", 1},
             Case{"[params]\nvec3 = 1\n", "GLSL keyword", 1},
             Case{"[params]\nframe = 1\n", "reserved", 1},
             Case{"[params]\ngl_Foo = 1\n", "reserved by GLSL", 1},
             Case{"[params]\na__b = 1\n", "reserved by GLSL", 1},
             Case{"[params]\n\"2x\" = 1\n", "must be an identifier", 1},
         }) {
        Error e = fails(c.text);
        EXPECT_TRUE(has(e.message, c.says)) << c.text << e.format();
        EXPECT_EQ(e.loc.line, 2) << c.text;
        EXPECT_EQ(e.loc.col, c.col) << c.text << e.format();
    }
}

TEST(Parse, MeshSimplify) {
    auto g = parse("[meshes]\n"
                   "a = { generator = \"teapot\", simplify = { ratio = 0.25 } }\n"
                   "b = { file = \"m.obj\", simplify = { triangles = 100, max_error = 0.01, morph = { ratio = 0.1 } } }\n"
                   "c = { generator = \"plane\", segments = 8, simplify = { max_error = 0.0 } }\n"
                   "[images]\nldr = { format = \"rgba8\" }\n[[pass]]\nname = \"p\"\nfragment = \"debug/uv.frag\"\ntargets = [\"ldr\"]\n");
    ASSERT_TRUE(g) << g.error().message;
    const MeshDesc* a = g->find_mesh("a");
    ASSERT_TRUE(a->simplify);
    EXPECT_EQ(a->simplify->target.ratio, 0.25);
    EXPECT_FALSE(a->simplify->target.triangles);
    EXPECT_FALSE(a->simplify->morph);
    EXPECT_EQ(a->keys.at("simplify.ratio", {}).line, 2);
    EXPECT_EQ(a->keys.at("simplify.ratio", {}).col, 50);
    const MeshDesc* b = g->find_mesh("b");  // a file mesh takes simplify too
    ASSERT_TRUE(b->simplify && b->simplify->morph);
    EXPECT_EQ(b->simplify->target.triangles, 100);
    EXPECT_EQ(b->simplify->target.max_error, 0.01);
    EXPECT_EQ(b->simplify->morph->ratio, 0.1);
    EXPECT_EQ(b->keys.at("simplify.morph.ratio", {}).line, 3);
    EXPECT_EQ(g->find_mesh("c")->simplify->target.max_error, 0.0);
    EXPECT_EQ(g->find_mesh("c")->args.at("segments"), 8);  // generator arguments unaffected

    const std::string tail = "\n[images]\nldr = { format = \"rgba8\" }\n[[pass]]\nname = \"p\"\nfragment = \"debug/uv.frag\"\ntargets = [\"ldr\"]\n";
    auto err = [&](const std::string& simplify) {
        return fails("[meshes]\nm = { generator = \"sphere\", simplify = " + simplify + " }" + tail);
    };
    EXPECT_TRUE(has(err("{ ratio = 0 }").message, "ratio must be in (0, 1], not 0"));
    EXPECT_TRUE(has(err("{ ratio = 0.5, triangles = 10 }").message, "give ratio or triangles, not both"));
    EXPECT_TRUE(has(err("{ }").message, "needs a target"));
    EXPECT_TRUE(has(err("{ triangles = 0 }").message, "triangles"));
    EXPECT_TRUE(has(err("{ max_error = -1 }").message, "max_error must be a finite distance >= 0"));
    EXPECT_TRUE(has(err("0.5").message, "a table"));
    EXPECT_TRUE(has(err("{ ratio = 0.5, morph = true }").message, "a table"));
    EXPECT_TRUE(has(err("{ ratio = 0.5, morph = { ratio = 0.5 } }").message, "must be coarser"));
    EXPECT_TRUE(has(err("{ ratio = 0.5, morph = { ratio = 0.2, morph = { ratio = 0.1 } } }").message, "unknown key 'morph'"));
    Error e = err("{ ratio = 0.5, morph = { ratoi = 0.2 } }");
    EXPECT_TRUE(has(e.message, "simplify.morph: unknown key 'ratoi'"));
    EXPECT_EQ(e.hint, "did you mean 'ratio'?");
}
