#version 450
// EXERCISE — cube environment mapping (000_c9f7e5de708ecbb3.txt L2341-2354): the environment is
// assumed infinitely far, so the lookup depends on a direction only, the reflection vector.
// Fill in the two TODO blocks; as shipped the object is drawn in its decal colour.
//     passlab run   envmap/cube-env-reflection --exercise presets/envmap/cube-env-reflection/exercise
//     passlab grade envmap/cube-env-reflection --exercise presets/envmap/cube-env-reflection/exercise
// v_world and v_normal are in world space, where the cube map was made (000 L2353): no view
// matrix is needed. frame.camera_pos.xyz is the eye in world space.
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
uniform samplerCube env;
void main() {
    vec3 n = normalize(v_normal);
    // TODO 1: the reflection vector of 000 L2350, R = V - 2 (N N^T) V = V - 2 (N.V) N, where V
    // is the unit vector from the eye TO the surface point (the incident direction: mind which
    // way it points) and N the unit normal.
    vec3 R = n;
    // TODO 2: look the environment up in direction R (texture() on a samplerCube takes the
    // direction itself, no normalisation needed) and blend it over the object's own colour:
    //     color = mix(decal, env(R), reflectivity)
    vec3 color = params.decal;
    hdr = vec4(color, 1.0);
}
