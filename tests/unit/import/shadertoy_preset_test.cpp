#include "import/import.hpp"
#include "import/toy.hpp"

#include <gtest/gtest.h>

using namespace pl::import;

namespace {

Tab tab(TabKind kind, int index, const std::string& file) {
    Tab t;
    t.kind = kind;
    t.index = index;
    t.file = file;
    t.label = kind == TabKind::image ? "Image" : kind == TabKind::sound ? "Sound" : buffer_label(index);
    t.code = "void mainImage(out vec4 c, in vec2 p) { c = vec4(0.0); }\n";
    return t;
}
Channel buf(int b, const std::string& filter = "linear") {
    Channel c;
    c.kind = ChannelKind::buffer;
    c.buffer = b;
    c.sampler.filter = filter;
    return c;
}
std::string toml_of(const Toy& toy) {
    auto p = shadertoy_preset(toy, ImportOptions{});
    EXPECT_TRUE(p.ok());
    return p->files.at("preset.toml");
}

} // namespace

// Buffer A reads B (later: previous frame) and itself; B reads A (earlier: current frame).
TEST(ImportShadertoy, HistoryOnlyForSelfAndLaterReads) {
    Toy toy;
    Tab a = tab(TabKind::buffer, 0, "buffer_a.glsl"), b = tab(TabKind::buffer, 1, "buffer_b.glsl"), i = tab(TabKind::image, 0, "image.glsl");
    a.channels[0] = buf(1);
    b.channels[0] = buf(0);
    i.channels[0] = buf(1);
    toy.tabs = {i, b, a};  // tab order in the source does not matter: A, B, then Image run
    const std::string t = toml_of(toy);
    EXPECT_NE(t.find("iChannel0 = \"buffer_b_prev\""), std::string::npos) << t;
    EXPECT_NE(t.find("buffer_b = { size = \"view\", format = \"rgba32f\", history = true"), std::string::npos) << t;
    EXPECT_NE(t.find("buffer_a = { size = \"view\", format = \"rgba32f\", sampler"), std::string::npos) << t;  // no history
    EXPECT_LT(t.find("name     = \"buffer_a\""), t.find("name     = \"buffer_b\""));
    EXPECT_LT(t.find("name     = \"buffer_b\""), t.find("name     = \"image\""));
}

TEST(ImportShadertoy, SecondSamplerIsAnAlias) {
    Toy toy;
    Tab a = tab(TabKind::buffer, 0, "buffer_a.glsl"), i = tab(TabKind::image, 0, "image.glsl");
    a.channels[0] = buf(0, "nearest");
    i.channels[1] = buf(0, "linear");
    toy.tabs = {a, i};
    const std::string t = toml_of(toy);
    EXPECT_NE(t.find("buffer_a_linear_clamp = { alias = \"buffer_a\""), std::string::npos) << t;
    EXPECT_NE(t.find("iChannel1 = \"buffer_a_linear_clamp\""), std::string::npos) << t;
    EXPECT_NE(t.find("iChannel0 = \"buffer_a_prev\""), std::string::npos) << t;
}

TEST(ImportShadertoy, SoundIsOneWarningAndMediaOneEach) {
    Toy toy;
    Tab i = tab(TabKind::image, 0, "image.glsl");
    i.channels[2].kind = ChannelKind::texture;
    i.channels[2].media = "/media/a/noise.png";
    toy.tabs = {tab(TabKind::sound, 0, "sound.glsl"), i};
    auto p = shadertoy_preset(toy, ImportOptions{});
    ASSERT_TRUE(p.ok());
    ASSERT_EQ(p->warnings.size(), 2u);
    EXPECT_NE(p->warnings[0].find("mainSound is not supported"), std::string::npos);
    EXPECT_NE(p->warnings[1].find("Image iChannel2"), std::string::npos);
    EXPECT_EQ(p->files.count("sound.glsl"), 0u);
}

TEST(ImportShadertoy, MissingBufferTabIsAnError) {
    Toy toy;
    Tab i = tab(TabKind::image, 0, "image.glsl");
    i.channels[0] = buf(2);
    toy.tabs = {i};
    auto s = check_toy(toy, {"x.json", 1, 1});
    ASSERT_FALSE(s.ok());
    EXPECT_NE(s.error().message.find("reads Buffer C, which has no tab"), std::string::npos);
}

TEST(ImportDetect, ByExtensionAndContent) {
    EXPECT_FALSE(detect_source(PASSLAB_TEST_DIR "/../presets/procedural/fbm").has_value());
    EXPECT_EQ(detect_source(PASSLAB_TEST_DIR "/import/order/src.json"), SourceKind::shadertoy_json);
    EXPECT_EQ(detect_source(PASSLAB_TEST_DIR "/import/alpha/src.frag"), SourceKind::shadertoy_file);
    EXPECT_EQ(detect_source(PASSLAB_TEST_DIR "/import/counter/src"), SourceKind::shadertoy_folder);
    EXPECT_EQ(detect_source(PASSLAB_TEST_DIR "/import/isf-vs/src.fs"), SourceKind::isf);
}
