#include "util/error.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

using namespace pl;

TEST(Error, FormatHasLocationPassResourceLineAndCaret) {
    auto path = std::filesystem::temp_directory_path() / "passlab_error_test.frag";
    {
        std::ofstream f(path);
        f << "#version 450\n\tvec3 c = colr;\n";
    }
    Error e = make_error("'colr' : undeclared identifier", {path.string(), 2, 11});
    e.pass = "shade";
    e.resource = "colr";
    e.hint = "did you mean 'color'?";
    std::string s = e.format();
    EXPECT_NE(s.find(path.string() + ":2:11: error: 'colr' : undeclared identifier [pass 'shade', resource 'colr']"),
              std::string::npos) << s;
    EXPECT_NE(s.find("    \tvec3 c = colr;\n"), std::string::npos) << s;
    EXPECT_NE(s.find("    \t         ^\n"), std::string::npos) << s;  // tab kept so the caret lines up
    EXPECT_NE(s.find("hint: did you mean 'color'?"), std::string::npos) << s;
    std::filesystem::remove(path);
}

TEST(Error, SourceLineSkipsBomAndCarriageReturn) {
    auto path = std::filesystem::temp_directory_path() / "passlab_bom_test.toml";
    {
        std::ofstream f(path, std::ios::binary);
        f << "\xEF\xBB\xBF[preset]\r\ntitle = 1\r\n";
    }
    EXPECT_EQ(read_source_line(path.string(), 1), "[preset]");
    EXPECT_EQ(read_source_line(path.string(), 2), "title = 1");
    EXPECT_EQ(read_source_line(path.string(), 3), "");
    std::filesystem::remove(path);
}

TEST(Error, NearestName) {
    EXPECT_EQ(nearest_name("albdo", {"albedo", "depth", "normal"}), "albedo");
    EXPECT_EQ(nearest_name("rgba16", {"rgba8", "rgba16f", "r32f"}), "rgba16f");
    EXPECT_EQ(nearest_name("zzzzzz", {"albedo", "depth"}), "");
    EXPECT_EQ(edit_distance("kitten", "sitting"), 3);
}
