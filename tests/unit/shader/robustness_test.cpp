// Inputs that once crashed or hung the shader front end (issue 18's fuzzing campaign): lines
// long enough to overflow std::regex's recursion, numbers too large for std::stoi, include
// chains thousands deep, names the file system refuses, and #version lines glslang rejects
// without a line. Each must end in a located pl::Error (or compile), quickly.
#include "shader/program.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>

#include <sys/stat.h>

namespace fs = std::filesystem;
using namespace pl;
using namespace pl::shader;

namespace {

class ShaderRobustness : public ::testing::Test {
  protected:
    void SetUp() override {
        dir = fs::temp_directory_path() / ("passlab_robust_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()) +
                                           "_" + ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::remove_all(dir);
        fs::create_directories(dir);
    }
    void TearDown() override {
        std::error_code ec;
        fs::remove_all(dir, ec);
    }
    fs::path write(const std::string& name, const std::string& text) {
        fs::create_directories((dir / name).parent_path());
        std::ofstream(dir / name, std::ios::binary) << text;
        return dir / name;
    }
    Result<Program> frag(const fs::path& f) {
        CompileOptions opt;
        return compile_program({{Stage::fragment, f, f.string(), {}}}, opt);
    }
    fs::path dir;
};

const std::string kBody = "layout(location = 0) out vec4 color;\nvoid main() { color = vec4(1.0); }\n";

} // namespace

TEST_F(ShaderRobustness, LongLinesAreScannedWithoutRecursion) {
    const std::string pad(60000, ' ');
    // Leading blanks, and long tails after the directives the host recognises.
    for (const std::string& line : {pad + "float x_ = 1.0;", "#pragma once" + pad, "#include \"" + std::string(60000, 'a') + "\"",
                                    "#version 450" + pad})
    {
        auto f = write("main.frag", (line.rfind("#version", 0) == 0 ? line + "\n" : "#version 450\n" + line + "\n") + kBody);
        auto p = frag(f);  // compiles or fails with a message; must not crash
        if (!p) {
            EXPECT_FALSE(p.error().message.empty());
        }
    }
}

TEST_F(ShaderRobustness, LongErrorMessageIsParsedWithoutRecursion) {
    auto f = write("main.frag", "#version 450\n#error " + std::string(60000, 'x') + "\n" + kBody);
    auto p = frag(f);
    ASSERT_FALSE(p);
    EXPECT_EQ(p.error().loc.line, 2) << p.error().loc.str();
}

TEST_F(ShaderRobustness, LineNumberTooLargeForAnIntIsNotAnAbort) {
    // A folder name holding ":99999999999: " looks like a log location to a naive parser.
    auto f = write("odd:99999999999: name/main.frag", "#version 450\n" + kBody + "void f() { undefined_x; }\n");
    auto p = frag(f);
    ASSERT_FALSE(p);
    EXPECT_EQ(p.error().loc.line, 4) << p.error().format();
    // The same through a #line name.
    auto g = write("main2.frag", "#version 450\n#extension GL_GOOGLE_cpp_style_line_directive : require\n#line 5 \"x:99999999999: y\"\n" + kBody +
                                     "void f() { undefined_x; }\n");
    auto q = frag(g);
    ASSERT_FALSE(q);
}

TEST_F(ShaderRobustness, DeepIncludeChainIsRefusedAtTheLimitQuickly) {
    const int depth = 3000;
    for (int i = 0; i < depth; ++i) write("inc" + std::to_string(i) + ".glsl", "#include \"inc" + std::to_string(i + 1) + ".glsl\"\n");
    write("inc" + std::to_string(depth) + ".glsl", "float leaf() { return 1.0; }\n");
    auto f = write("main.frag", "#version 450\n#include \"inc0.glsl\"\n" + kBody);
    auto t0 = std::chrono::steady_clock::now();
    auto p = frag(f);
    double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    ASSERT_FALSE(p);
    EXPECT_NE(p.error().message.find("nested more than 64 deep"), std::string::npos) << p.error().format();
    EXPECT_NE(p.error().loc.file.find(".glsl"), std::string::npos);
    EXPECT_GT(p.error().loc.line, 0);
    EXPECT_LT(s, 10.0);  // a hang guard, not a timing test: depth 2,000 took 34 s before
}

TEST_F(ShaderRobustness, IncludeChainWithinTheLimitCompiles) {
    for (int i = 0; i < 60; ++i) write("c" + std::to_string(i) + ".glsl", "#include \"c" + std::to_string(i + 1) + ".glsl\"\n");
    write("c60.glsl", "float leaf() { return 1.0; }\n");
    auto f = write("main.frag", "#version 450\n#include \"c0.glsl\"\n" + kBody);
    auto p = frag(f);
    EXPECT_TRUE(p) << p.error().format();
}

TEST_F(ShaderRobustness, SymlinkLoopAndOverlongNameAreLocatedErrors) {
    fs::create_symlink("loop.glsl", dir / "loop.glsl");
    auto f = write("main.frag", "#version 450\n#include \"loop.glsl\"\n" + kBody);
    auto p = frag(f);
    ASSERT_FALSE(p);
    EXPECT_EQ(p.error().loc.line, 2) << p.error().format();
    auto g = write("long.frag", "#version 450\n#include \"" + std::string(300, 'n') + ".glsl\"\n" + kBody);
    auto q = frag(g);
    ASSERT_FALSE(q);
    EXPECT_EQ(q.error().loc.line, 2) << q.error().format();
}

TEST_F(ShaderRobustness, IncludeOfAFifoIsRefused) {
    ASSERT_EQ(::mkfifo((dir / "pipe.glsl").c_str(), 0600), 0);
    auto f = write("main.frag", "#version 450\n#include \"pipe.glsl\"\n" + kBody);
    auto p = frag(f);
    ASSERT_FALSE(p);
    EXPECT_EQ(p.error().loc.line, 2) << p.error().format();
}

TEST_F(ShaderRobustness, OldOrEsVersionIsReportedAtItsLine) {
    for (const char* v : {"#version 300 es", "#version 110", "  #version 100"}) {
        auto f = write("main.frag", std::string("// a comment first\n") + v + "\n" + kBody);
        auto p = frag(f);
        ASSERT_FALSE(p) << v;
        EXPECT_EQ(p.error().loc.line, 2) << p.error().format();
        EXPECT_GT(p.error().loc.col, 0) << p.error().format();
        EXPECT_NE(p.error().message.find("#version 450"), std::string::npos) << p.error().format();
    }
    for (const char* v : {"#version 450", "#version 460 core", "#version 310 es"}) {
        auto f = write("main.frag", std::string(v) + "\n" + kBody);
        auto p = frag(f);
        EXPECT_TRUE(p || p.error().message.find("passlab compiles") == std::string::npos) << v;
    }
}

TEST_F(ShaderRobustness, VertexShaderWithoutMainIsBlamedOnTheVertexFile) {
    auto v = write("v.vert", "#version 450\nvoid not_main() {}\n");
    auto f = write("f.frag", "#version 450\n" + kBody);
    CompileOptions opt;
    auto p = compile_program({{Stage::vertex, v, v.string(), {}}, {Stage::fragment, f, f.string(), {}}}, opt);
    ASSERT_FALSE(p);
    EXPECT_EQ(p.error().loc.file, v.string()) << p.error().format();
    EXPECT_NE(p.error().message.find("vertex shader"), std::string::npos) << p.error().format();
}

TEST_F(ShaderRobustness, NewlineInAFolderNameStaysOutOfThePreamble) {
    auto f = write("odd\nfolder/main.frag", "#version 450\n" + kBody + "void f() { undefined_x; }\n");
    auto p = frag(f);
    ASSERT_FALSE(p);
    EXPECT_EQ(p.error().loc.file.find("preamble"), std::string::npos) << p.error().format();
    EXPECT_EQ(p.error().loc.line, 4) << p.error().format();
    EXPECT_NE(p.error().message.find("undefined_x"), std::string::npos) << p.error().format();
}

// The reflector also reads SPIR-V from the on-disk cache, which a crash mid-write can leave cut
// anywhere (fuzz_spirv found the first case: an OpSpecConstant of one word at the module's end).
// Every instruction of a real module, cut to each shorter length as the module's last words,
// must be refused as malformed or reflected, never read past; under ASan (the CI sanitizer
// stage) a read past the vector fails this test. Seen failing (ASan heap-buffer-overflow at
// reflect.cpp's operand reads) with the min_words() check removed.
TEST_F(ShaderRobustness, SpirvCutInsideAnInstructionIsRefusedNotReadPast) {
    auto f = write("main.frag", "#version 450\nlayout(set = 0, binding = 0) uniform sampler2D tex;\n"
                                "layout(push_constant) uniform P { vec4 tint; float s[4]; } pc;\n"
                                "layout(location = 0) out vec4 color;\n"
                                "void main() { color = texture(tex, vec2(0.5)) * pc.tint * pc.s[2]; }\n");
    auto p = frag(f);
    ASSERT_TRUE(p) << p.error().format();
    const std::vector<uint32_t>& w = p->stages.at(0).words;
    int refused = 0, cuts = 0;
    for (size_t i = 5; i < w.size();) {
        const uint32_t op = w[i] & 0xffff, len = w[i] >> 16;
        ASSERT_GT(len, 0u);
        for (uint32_t cut = 1; cut < len; ++cut) {
            std::vector<uint32_t> v(w.begin(), w.begin() + static_cast<std::ptrdiff_t>(i + cut));
            v[i] = (cut << 16) | op;  // the instruction claims exactly the words left
            auto r = reflect_spirv(v, Stage::fragment);
            (void)private_memory_bytes(v);
            (void)workgroup_memory_bytes(v);
            ++cuts;
            if (!r) ++refused;
        }
        i += len;
    }
    // The module has names, decorations, types, constants and variables, each of which the
    // reflector reads operands of; a cut of one of them is refused.
    EXPECT_GT(cuts, 100);
    EXPECT_GT(refused, 50);
}
