// Shader front end: include expansion with #line mapping, error locations through includes,
// cycles, BOM/CRLF, reflection, the private-memory guard and the SPIR-V cache.
#include "shader/program.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace pl;
using namespace pl::shader;

namespace {

class ShaderTest : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("passlab_shader_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                           "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir / "lib");
    }
    void TearDown() override { fs::remove_all(dir); }
    fs::path write(const std::string& name, const std::string& text) {
        std::ofstream(dir / name, std::ios::binary) << text;
        return dir / name;
    }
    Result<Program> frag(const fs::path& f, CompileOptions opt = {}) {
        opt.include_dirs.push_back(dir / "lib");
        return compile_program({{Stage::fragment, f, f.string(), {}}}, opt);
    }
    fs::path dir;
};

const char* kOut = "layout(location = 0) out vec4 color;\n";

} // namespace

TEST_F(ShaderTest, ErrorInIncludedFileReportsThatFileAndLine) {
    write("lib/helpers.glsl", "float helper(float x) {\n    return x * 2.0;\n}\nfloat broken() {\n    return undefined_thing;\n}\n");
    auto f = write("main.frag", std::string("#version 450\n#include \"helpers.glsl\"\n") + kOut + "void main() { color = vec4(helper(1.0)); }\n");
    auto p = frag(f);
    ASSERT_FALSE(p);
    EXPECT_NE(p.error().loc.file.find("helpers.glsl"), std::string::npos) << p.error().format();
    EXPECT_EQ(p.error().loc.line, 5) << p.error().format();
    EXPECT_EQ(p.error().loc.col, 12) << p.error().format();  // column of 'undefined_thing'
    EXPECT_EQ(p.error().source_line, "    return undefined_thing;");
}

TEST_F(ShaderTest, ErrorAfterIncludeInMainFileKeepsMainLineNumbers) {
    write("lib/a.glsl", "float a() { return 1.0; }\nfloat b() { return 2.0; }\nfloat c() { return 3.0; }\n");
    auto f = write("main.frag", std::string("#version 450\n#include \"a.glsl\"\n") + kOut + "void main() {\n    color = vec4(colr);\n}\n");
    auto p = frag(f);
    ASSERT_FALSE(p);
    EXPECT_EQ(p.error().loc.file, f.string());
    EXPECT_EQ(p.error().loc.line, 5);
    EXPECT_NE(p.error().message.find("'colr'"), std::string::npos);
    EXPECT_NE(p.error().message.find("fragment shader"), std::string::npos);
}

TEST_F(ShaderTest, PreambleDoesNotShiftLines) {
    CompileOptions opt;
    for (int i = 0; i < 20; ++i) opt.preamble += "// preamble line " + std::to_string(i) + "\n";
    opt.preamble += "const float kInjected = 1.0;\n";
    auto f = write("main.frag", std::string("#version 450\n") + kOut + "void main() {\n    color = vec4(kInjected) + bad;\n}\n");
    auto p = frag(f, opt);
    ASSERT_FALSE(p);
    EXPECT_EQ(p.error().loc.line, 4);
}

TEST_F(ShaderTest, MissingVersionGets450) {
    auto f = write("main.frag", std::string(kOut) + "void main() { color = vec4(1); }\n");
    EXPECT_TRUE(frag(f)) ;
}

TEST_F(ShaderTest, MissingIncludeNamesTheIncludeLine) {
    auto f = write("main.frag", std::string("#version 450\n\n#include \"nowhere.glsl\"\n") + kOut + "void main() {}\n");
    auto p = frag(f);
    ASSERT_FALSE(p);
    EXPECT_EQ(p.error().loc.line, 3);
    EXPECT_NE(p.error().message.find("nowhere.glsl"), std::string::npos);
    EXPECT_FALSE(p.error().notes.empty());  // where it looked
}

TEST_F(ShaderTest, SelfIncludeAndCyclesAreReportedQuickly) {
    auto t0 = std::chrono::steady_clock::now();
    write("lib/self.glsl", "#include \"self.glsl\"\n");
    auto f1 = write("a.frag", std::string("#version 450\n#include \"self.glsl\"\n") + kOut + "void main() {}\n");
    auto p1 = frag(f1);
    ASSERT_FALSE(p1);
    EXPECT_NE(p1.error().message.find("includ"), std::string::npos) << p1.error().format();
    EXPECT_NE(p1.error().loc.file.find("self.glsl"), std::string::npos) << p1.error().format();

    write("lib/x.glsl", "float x();\n#include \"y.glsl\"\n");
    write("lib/y.glsl", "#include \"x.glsl\"\n");
    auto f2 = write("b.frag", std::string("#version 450\n#include \"x.glsl\"\n") + kOut + "void main() {}\n");
    auto p2 = frag(f2);
    ASSERT_FALSE(p2);
    std::string msg = p2.error().format();
    EXPECT_NE(msg.find("cycle"), std::string::npos) << msg;
    EXPECT_NE(msg.find("x.glsl:2 includes"), std::string::npos) << msg;
    EXPECT_NE(msg.find("y.glsl"), std::string::npos) << msg;
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(5));
}

TEST_F(ShaderTest, BomAndCrlfAreAccepted) {
    auto f = write("bom.frag", std::string("\xEF\xBB\xBF#version 450\r\n") + "layout(location = 0) out vec4 color;\r\nvoid main() { color = vec4(1); }\r\n");
    auto p = frag(f);
    EXPECT_TRUE(p) << (p ? "" : p.error().format());
}

TEST_F(ShaderTest, ReflectsResourcesByName) {
    auto f = write("r.frag", std::string("#version 450\n") + kOut +
                                 "uniform sampler2D albedo;\n"
                                 "uniform sampler2DShadow shadow_map;\n"
                                 "uniform samplerCube env;\n"
                                 "uniform sampler2DArray layers;\n"
                                 "uniform usampler2D ids;\n"
                                 "layout(rgba16f) uniform image2D img;\n"
                                 "layout(std430) readonly buffer Nodes { uint count; vec4 data[]; } nodes;\n"
                                 "layout(std140) uniform Light { vec4 pos; vec4 color; } light;\n"
                                 "layout(push_constant) uniform Push { int i; float f; } push;\n"
                                 "void main() { color = texture(albedo, vec2(0)) + texture(shadow_map, vec3(0)) +\n"
                                 "  texture(env, vec3(1)) + texture(layers, vec3(0)) + vec4(texture(ids, vec2(0))) +\n"
                                 "  imageLoad(img, ivec2(0)) + nodes.data[0] + light.pos + vec4(push.i + push.f); }\n");
    auto p = frag(f);
    ASSERT_TRUE(p) << p.error().format();
    const auto& r = p->reflection;
    auto b = [&](const char* n) { return r.find(n); };
    ASSERT_TRUE(b("albedo"));
    EXPECT_EQ(b("albedo")->type, BindingType::combined_image_sampler);
    EXPECT_EQ(b("albedo")->dim, ImageDim::d2);
    ASSERT_TRUE(b("shadow_map"));
    EXPECT_TRUE(b("shadow_map")->shadow);
    EXPECT_EQ(b("env")->dim, ImageDim::cube);
    EXPECT_TRUE(b("layers")->arrayed);
    EXPECT_TRUE(b("ids")->is_integer);
    ASSERT_TRUE(b("img"));
    EXPECT_EQ(b("img")->type, BindingType::storage_image);
    EXPECT_EQ(b("img")->storage_format, "rgba16f");
    ASSERT_TRUE(b("nodes"));
    EXPECT_EQ(b("nodes")->type, BindingType::storage_buffer);
    EXPECT_EQ(b("nodes")->block_name, "Nodes");
    EXPECT_TRUE(b("nodes")->non_writable);
    ASSERT_TRUE(b("light"));
    EXPECT_EQ(b("light")->type, BindingType::uniform_buffer);
    EXPECT_EQ(b("light")->block_size, 32u);
    EXPECT_EQ(r.push_constant_size, 8u);
    EXPECT_EQ(r.fragment_output_count, 1u);
    // Auto-mapped bindings are distinct.
    for (size_t i = 0; i < r.bindings.size(); ++i)
        for (size_t j = i + 1; j < r.bindings.size(); ++j)
            EXPECT_FALSE(r.bindings[i].set == r.bindings[j].set && r.bindings[i].binding == r.bindings[j].binding);
}

TEST_F(ShaderTest, BindingsAgreeAcrossStages) {
    auto v = write("s.vert", "#version 450\nlayout(std140) uniform Shared { mat4 m; } shared_block;\nuniform sampler2D heights;\n"
                             "void main() { gl_Position = shared_block.m * vec4(textureLod(heights, vec2(0), 0).r); }\n");
    auto f = write("s.frag", std::string("#version 450\n") + kOut +
                                 "uniform sampler2D albedo;\nlayout(std140) uniform Shared { mat4 m; } shared_block;\n"
                                 "void main() { color = shared_block.m[0] + texture(albedo, vec2(0)); }\n");
    auto p = compile_program({{Stage::vertex, v, v.string(), {}}, {Stage::fragment, f, f.string(), {}}}, {});
    ASSERT_TRUE(p) << p.error().format();
    const Binding* s = p->reflection.find("shared_block");
    ASSERT_TRUE(s);
    EXPECT_EQ(s->stages, (1u << int(Stage::vertex)) | (1u << int(Stage::fragment)));
    EXPECT_NE(p->reflection.find("albedo")->binding, s->binding);
    EXPECT_NE(p->reflection.find("heights")->binding, s->binding);
}

TEST_F(ShaderTest, ComputeLocalSizeFromLocalSizeId) {
    auto c = write("c.comp", "#version 450\nlayout(local_size_x = 8, local_size_y = 4) in;\n"
                             "layout(r32f) uniform image2D img;\nvoid main() { imageStore(img, ivec2(gl_GlobalInvocationID.xy), vec4(1)); }\n");
    auto p = compile_program({{Stage::compute, c, c.string(), {}}}, {});
    ASSERT_TRUE(p) << p.error().format();
    EXPECT_EQ(p->reflection.local_size[0], 8u);
    EXPECT_EQ(p->reflection.local_size[1], 4u);
    EXPECT_EQ(p->reflection.local_size[2], 1u);
}

TEST_F(ShaderTest, HugeLocalArrayIsRefused) {
    auto t0 = std::chrono::steady_clock::now();
    auto f = write("big.frag", std::string("#version 450\n") + kOut +
                                   "void main() {\n    float a[50000000];\n    for (int i = 0; i < 50000000; ++i) a[i] = float(i);\n"
                                   "    color = vec4(a[int(gl_FragCoord.x)]);\n}\n");
    auto p = frag(f);
    ASSERT_FALSE(p);
    EXPECT_NE(p.error().message.find("20000000"), std::string::npos) << p.error().format();  // 5e7 floats + the loop counter
    EXPECT_NE(p.error().message.find("bytes"), std::string::npos);
    EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(10));
}

TEST_F(ShaderTest, CacheHitsAndMissesOnIncludeChange) {
    write("lib/k.glsl", "const float K = 1.0;\n");
    auto f = write("c.frag", std::string("#version 450\n#include \"k.glsl\"\n") + kOut + "void main() { color = vec4(K); }\n");
    CompileOptions opt;
    opt.cache_dir = dir / "cache";
    auto a = frag(f, opt);
    ASSERT_TRUE(a);
    EXPECT_FALSE(a->from_cache);
    auto b = frag(f, opt);
    ASSERT_TRUE(b);
    EXPECT_TRUE(b->from_cache);
    EXPECT_EQ(a->stages[0].words, b->stages[0].words);
    EXPECT_EQ(b->dependencies.size(), 2u);  // the shader and its include, even on a hit
    write("lib/k.glsl", "const float K = 2.0;\n");
    auto c = frag(f, opt);
    ASSERT_TRUE(c);
    EXPECT_FALSE(c->from_cache);
}

// A misspelt member of a uniform block (params.X, frame.X, a user's block) is answered with the
// nearest member and the list of members, at the misspelling's file:line:col.
TEST_F(ShaderTest, MisspeltBlockMemberSuggestsTheNearest) {
    auto f = write("typo.frag", std::string("#version 450\n") + kOut +
                                    "layout(set = 0, binding = 0) uniform Params { float scale; int octaves; vec4 tint[2]; } params;\n"
                                    "void main() { color = vec4(params.scael); }\n");
    auto p = frag(f);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().loc.line, 4);
    EXPECT_GT(p.error().loc.col, 0);
    EXPECT_EQ(p.error().hint, "did you mean 'params.scale'?") << p.error().format();
    ASSERT_FALSE(p.error().notes.empty());
    EXPECT_EQ(p.error().notes.front(), "params has: scale, octaves, tint");
}

TEST_F(ShaderTest, AFieldFarFromEveryMemberGetsOnlyTheList) {
    auto f = write("far.frag", std::string("#version 450\n") + kOut +
                                   "layout(set = 0, binding = 0) uniform Params { float scale; } params;\n"
                                   "void main() { color = vec4(params.brightness); }\n");
    auto p = frag(f);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().hint.find("did you mean"), std::string::npos) << p.error().hint;
    ASSERT_FALSE(p.error().notes.empty());
    EXPECT_EQ(p.error().notes.front(), "params has: scale");
}

// One build shows every independent mistake: the first as the error, the later ones (each once,
// by line, with its own "did you mean") as notes; glslang's enhanced messages alone stop at one.
TEST_F(ShaderTest, EveryIndependentErrorIsReported) {
    auto f = write("three.frag", std::string("#version 450\n") + kOut +
                                     "layout(set = 0, binding = 0) uniform Params { float scale; } params;\n"
                                     "void main() {\n"
                                     "    vec3 n = normalise(vec3(1.0));\n"
                                     "    float s = params.scael;\n"
                                     "    color = vec4(n * s, 1.0) + undefined_thing;\n"
                                     "}\n");
    auto p = frag(f);
    ASSERT_FALSE(p.ok());
    EXPECT_EQ(p.error().loc.line, 5) << p.error().format();
    EXPECT_NE(p.error().message.find("'normalise'"), std::string::npos) << p.error().format();
    std::string notes;
    for (const auto& n : p.error().notes) notes += n + "\n";
    EXPECT_NE(notes.find("three.frag:6:"), std::string::npos) << notes;
    EXPECT_NE(notes.find("did you mean 'params.scale'?"), std::string::npos) << notes;
    EXPECT_NE(notes.find("three.frag:7:"), std::string::npos) << notes;
    EXPECT_NE(notes.find("'undefined_thing'"), std::string::npos) << notes;
    EXPECT_EQ(notes.find("three.frag:5:"), std::string::npos) << "a follow-up of the first error is repeated:\n" << notes;
    EXPECT_EQ(notes.find("compilation terminated"), std::string::npos) << notes;
}

// After a syntax error only that error is shown: what the parser reports past it is its recovery.
TEST_F(ShaderTest, ASyntaxErrorIsReportedAlone) {
    auto f = write("syntax.frag", std::string("#version 450\n") + kOut +
                                      "void main() {\n"
                                      "    float a = 1.0\n"
                                      "    color = vec4(a) + undefined_thing;\n"
                                      "}\n");
    auto p = frag(f);
    ASSERT_FALSE(p.ok());
    for (const auto& n : p.error().notes) EXPECT_EQ(n.find("undefined_thing"), std::string::npos) << n;
}

// A syntax error quotes nothing ("'' : syntax error, unexpected SEMICOLON, expecting
// RIGHT_PAREN or COMMA"); its column is the unexpected token's, found from the grammar's token
// name. Before culprit.cpp, 35% of the syntax errors in a sample of 162 broken preset shaders
// had no column (the measure is in tests/fuzz/README.md). Seen failing with the token lookup
// removed (every column 0, but the keyword case).
TEST_F(ShaderTest, SyntaxErrorColumnIsTheUnexpectedToken) {
    struct Case {
        const char* body;  // the line glslang reports, then what makes it an error
        int line, col;
    } cases[] = {
        {"void main() {\n    color = vec4(0.5;\n}\n", 4, 21},                   // SEMICOLON: the unclosed call
        {"void main() {\n    float mm  0.0;\n    color = vec4(mm);\n}\n", 4, 15},  // FLOATCONSTANT
        {"void main( { color = vec4(1); }\n", 3, 12},                            // LEFT_BRACE
        {"void main() {\n    float a = 1.0\n    a += 2.0;\n    color = vec4(a);\n}\n", 5, 5},  // IDENTIFIER after a missing ';'
        {"void main() { color = vec4(0.97, 0.96, 0.93, 1.0) }\n", 3, 51},        // RIGHT_BRACE
        {"void main() {\n    color = vec4(1) // (\n    return;\n}\n", 5, 5},     // RETURN, a keyword token
    };
    for (const auto& c : cases) {
        auto f = write("syntax.frag", std::string("#version 450\n") + kOut + c.body);
        auto p = frag(f);
        ASSERT_FALSE(p.ok()) << c.body;
        EXPECT_EQ(p.error().loc.line, c.line) << p.error().format();
        EXPECT_EQ(p.error().loc.col, c.col) << p.error().format();
    }
}
