// The column of a glslang message's culprit (see culprit.hpp). A syntax error names the token
// class bison saw, not the text ("unexpected RIGHT_BRACE"), and quotes nothing, so the text is
// looked up here: the token names are those of glslang's grammar (MachineIndependent/glslang.y).
// The parser reports the first token it could not use, which is the first of its kind on the
// line in the common cases (an unclosed call ends at its ';', a missing ';' at the next name);
// when the kind repeats on the line the column may be an earlier one, still on the right line.
#include "shader/culprit.hpp"
#include "util/scan.hpp"

#include <array>
#include <cctype>
#include <string_view>

namespace pl::shader {

namespace {

struct Lexeme {
    std::string_view token, text;
};

// Punctuation and operators by grammar name, each one exact text searched as a substring; the
// constants have no fixed text and are found by kind (find_constant).
constexpr std::array<Lexeme, 49> kLexemes{{
    {"LEFT_ASSIGN", "<<="}, {"RIGHT_ASSIGN", ">>="}, {"LEFT_OP", "<<"}, {"RIGHT_OP", ">>"},
    {"INC_OP", "++"}, {"DEC_OP", "--"}, {"LE_OP", "<="}, {"GE_OP", ">="}, {"EQ_OP", "=="},
    {"NE_OP", "!="}, {"AND_OP", "&&"}, {"OR_OP", "||"}, {"XOR_OP", "^^"}, {"MUL_ASSIGN", "*="},
    {"DIV_ASSIGN", "/="}, {"ADD_ASSIGN", "+="}, {"MOD_ASSIGN", "%="}, {"AND_ASSIGN", "&="},
    {"XOR_ASSIGN", "^="}, {"OR_ASSIGN", "|="}, {"SUB_ASSIGN", "-="}, {"LEFT_PAREN", "("},
    {"RIGHT_PAREN", ")"}, {"LEFT_BRACKET", "["}, {"RIGHT_BRACKET", "]"}, {"LEFT_BRACE", "{"},
    {"RIGHT_BRACE", "}"}, {"DOT", "."}, {"COMMA", ","}, {"COLON", ":"}, {"EQUAL", "="},
    {"SEMICOLON", ";"}, {"BANG", "!"}, {"DASH", "-"}, {"TILDE", "~"}, {"PLUS", "+"}, {"STAR", "*"},
    {"SLASH", "/"}, {"PERCENT", "%"}, {"LEFT_ANGLE", "<"}, {"RIGHT_ANGLE", ">"},
    {"VERTICAL_BAR", "|"}, {"CARET", "^"}, {"AMPERSAND", "&"}, {"QUESTION", "?"},
    {"BOOLCONSTANT", ""}, {"INTCONSTANT", ""}, {"UINTCONSTANT", ""}, {"FLOATCONSTANT", ""},
}};

bool ident_start(char c) { return std::isalpha(static_cast<unsigned char>(c)) || c == '_'; }
bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Words the grammar has its own token for, so "unexpected IDENTIFIER" never means one of them.
bool is_keyword(std::string_view w) {
    static constexpr std::string_view kWords[] = {
        "attribute", "const", "uniform", "buffer", "shared", "in", "out", "inout", "layout", "flat", "smooth",
        "noperspective", "centroid", "sample", "patch", "highp", "mediump", "lowp", "precision", "invariant",
        "precise", "coherent", "volatile", "restrict", "readonly", "writeonly", "struct", "void", "bool", "int",
        "uint", "float", "double", "return", "if", "else", "for", "while", "do", "switch", "case", "default",
        "break", "continue", "discard", "true", "false"};
    for (auto k : kWords)
        if (w == k) return true;
    // vec3, ivec2, mat4x3, dmat2, sampler2D, image2D, ... are type keywords too.
    for (std::string_view prefix : {"vec", "ivec", "uvec", "bvec", "dvec", "mat", "dmat", "sampler", "isampler",
                                    "usampler", "image", "iimage", "uimage", "texture", "subpassInput"})
        if (w.size() > prefix.size() && w.substr(0, prefix.size()) == prefix &&
            (std::isdigit(static_cast<unsigned char>(w[prefix.size()])) || std::isupper(static_cast<unsigned char>(w[prefix.size()]))))
            return true;
    return false;
}

// Index of the first literal of the kind in `s` (not inside a name), npos if none.
size_t find_constant(std::string_view s, std::string_view token) {
    if (token == "BOOLCONSTANT") {
        size_t t = scan::find_word(s, "true"), f = scan::find_word(s, "false");
        return t < f ? t : f;
    }
    for (size_t i = 0; i < s.size(); ++i) {
        if (ident_char(s[i]) && !std::isdigit(static_cast<unsigned char>(s[i]))) {
            while (i + 1 < s.size() && ident_char(s[i + 1])) ++i;  // skip a whole name (vec3, x2)
            continue;
        }
        const bool starts_number = std::isdigit(static_cast<unsigned char>(s[i])) ||
                                   (s[i] == '.' && i + 1 < s.size() && std::isdigit(static_cast<unsigned char>(s[i + 1])));
        if (!starts_number) continue;
        size_t e = i;
        while (e < s.size() && (ident_char(s[e]) || s[e] == '.')) ++e;
        std::string_view lit = s.substr(i, e - i);
        const bool is_float = lit.find_first_of(".eEfF") != std::string_view::npos && lit.substr(0, 2) != "0x";
        const bool is_uint = !is_float && (lit.back() == 'u' || lit.back() == 'U');
        if ((token == "FLOATCONSTANT" && is_float) || (token == "UINTCONSTANT" && is_uint) ||
            (token == "INTCONSTANT" && !is_float && !is_uint))
            return i;
        i = e - 1;
    }
    return std::string_view::npos;
}

size_t find_identifier(std::string_view s) {
    for (size_t i = 0; i < s.size();) {
        if (!ident_start(s[i]) || (i > 0 && ident_char(s[i - 1]))) {
            ++i;
            continue;
        }
        size_t e = i;
        while (e < s.size() && ident_char(s[e])) ++e;
        if (!is_keyword(s.substr(i, e - i))) return i;
        i = e;
    }
    return std::string_view::npos;
}

} // namespace

int culprit_column(const std::string& msg, const std::string& source) {
    if (source.empty()) return 0;
    if (size_t a = msg.find('\''); a != std::string::npos)
        if (size_t b = msg.find('\'', a + 1); b != std::string::npos && b > a + 1)
            if (size_t p = source.find(msg.substr(a + 1, b - a - 1)); p != std::string::npos) return static_cast<int>(p) + 1;
    const std::string_view unexpected = "syntax error, unexpected ";
    const size_t u = msg.find(unexpected);
    if (u == std::string::npos) return 0;
    size_t end = u + unexpected.size();
    while (end < msg.size() && (std::isupper(static_cast<unsigned char>(msg[end])) ||
                                std::isdigit(static_cast<unsigned char>(msg[end])) || msg[end] == '_'))
        ++end;
    const std::string_view token = std::string_view(msg).substr(u + unexpected.size(), end - u - unexpected.size());
    // Only the code before a line comment counts: `// (x` is not the parenthesis glslang meant.
    std::string_view code(source);
    if (size_t c = code.find("//"); c != std::string_view::npos) code = code.substr(0, c);
    size_t p = std::string_view::npos;
    if (token == "IDENTIFIER" || token == "TYPE_NAME") {
        p = find_identifier(code);
    } else {
        bool named = false;
        for (const auto& l : kLexemes)
            if (l.token == token) {
                named = true;
                p = l.text.empty() ? find_constant(code, token) : code.find(l.text);
                break;
            }
        if (!named) {  // a keyword token: RETURN, VEC3, UNIFORM ... is the word in lower case
            std::string word;
            for (char c : token) word += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
            p = scan::find_word(code, word);
        }
    }
    return p == std::string_view::npos ? 0 : static_cast<int>(p) + 1;
}

} // namespace pl::shader
