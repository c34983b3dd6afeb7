#include "shader/bindings.hpp"
#include "shader/spirv_words.hpp"

#include <map>
#include <set>

namespace pl::shader {

namespace {

struct Decorated {
    std::string name;
    uint32_t set = 0, binding = 0;
    size_t binding_word = 0;  // index of the Binding operand in the module's words
};


// Every variable with a Binding decoration, named by its OpName or, for nameless block
// instances, by its block type's name (as reflection names them).
std::vector<Decorated> decorated(const std::vector<uint32_t>& w) {
    std::map<uint32_t, std::string> names;
    std::map<uint32_t, uint32_t> set_of, pointee_of, var_type;
    std::map<uint32_t, size_t> binding_at;
    for (size_t i = 5; i < w.size();) {
        uint32_t op = w[i] & 0xffff, len = w[i] >> 16;
        if (len == 0 || i + len > w.size()) break;
        if (op == 5 && len >= 2) names[w[i + 1]] = spirv_string(w, i + 2, i + len);    // OpName
        if (op == 71 && len >= 4 && w[i + 2] == 33) binding_at[w[i + 1]] = i + 3;    // Binding
        if (op == 71 && len >= 4 && w[i + 2] == 34) set_of[w[i + 1]] = w[i + 3];     // DescriptorSet
        if (op == 32 && len >= 4) pointee_of[w[i + 1]] = w[i + 3];                    // OpTypePointer
        if (op == 59 && len >= 4) var_type[w[i + 2]] = w[i + 1];                      // OpVariable
        i += len;
    }
    std::vector<Decorated> out;
    for (auto [id, word] : binding_at) {
        Decorated d;
        d.name = names.count(id) ? names[id] : "";
        if (d.name.empty() && var_type.count(id)) {
            uint32_t t = pointee_of[var_type[id]];
            d.name = names.count(t) ? names[t] : "";
        }
        d.set = set_of.count(id) ? set_of[id] : 0;
        d.binding = w[word];
        d.binding_word = word;
        out.push_back(d);
    }
    return out;
}

} // namespace

void unify_bindings(std::vector<StageSpirv>& stages) {
    std::vector<std::vector<Decorated>> per_stage;
    for (const auto& s : stages) per_stage.push_back(decorated(s.words));

    // A name keeps its number if every stage agrees on it and no other name uses it anywhere.
    std::map<std::pair<uint32_t, std::string>, std::set<uint32_t>> numbers;  // (set,name) -> bindings seen
    std::map<std::pair<uint32_t, uint32_t>, std::set<std::string>> users;    // (set,binding) -> names
    for (const auto& v : per_stage)
        for (const auto& d : v) {
            numbers[{d.set, d.name}].insert(d.binding);
            users[{d.set, d.binding}].insert(d.name);
        }
    std::map<std::pair<uint32_t, std::string>, uint32_t> final_binding;
    std::map<uint32_t, std::set<uint32_t>> taken;  // set -> bindings in use
    for (const auto& [key, nums] : numbers) {
        if (nums.size() == 1 && users[{key.first, *nums.begin()}].size() == 1) {
            final_binding[key] = *nums.begin();
            taken[key.first].insert(*nums.begin());
        }
    }
    for (const auto& [key, nums] : numbers) {
        if (final_binding.count(key)) continue;
        uint32_t b = 0;
        while (taken[key.first].count(b)) ++b;
        final_binding[key] = b;
        taken[key.first].insert(b);
    }
    for (size_t s = 0; s < stages.size(); ++s)
        for (const auto& d : per_stage[s]) stages[s].words[d.binding_word] = final_binding[{d.set, d.name}];
}

} // namespace pl::shader
