// Cross-stage binding agreement. glslang auto-maps bindings per stage, so the same uniform can
// get different numbers in the vertex and fragment stage, or two different names the same
// number. Since the host binds by name, we rewrite the SPIR-V Binding decorations so that one
// name has one binding in every stage of a pass. Numbers the user wrote are kept whenever they
// are consistent and collide with nothing.
#pragma once

#include "shader/program.hpp"

namespace pl::shader {

void unify_bindings(std::vector<StageSpirv>& stages);

} // namespace pl::shader
