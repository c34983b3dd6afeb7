#include "graph/camera_values.hpp"

#include <charconv>
#include <cmath>
#include <tuple>

namespace pl::graph {

namespace {

std::string num(double d) {
    char buf[32];
    auto r = std::to_chars(buf, buf + sizeof buf, d);
    return std::string(buf, r.ptr);
}

struct CameraEval {
    const CameraDesc& c;
    const SizeEnv& env;

    Error fail(const std::string& key, const std::string& msg, const SourceLoc& at) const {
        return make_error("camera '" + c.name + "': " + key + " " + msg, at.known() ? at : c.loc);
    }
    // Expression errors already point at their token; they gain the camera and key.
    Error wrap(const std::string& key, Error e) const {
        e.message = "camera '" + c.name + "': " + key + ": " + e.message;
        return e;
    }

    Status scalar(const std::string& key, const FloatExpr& e, double& out) const {
        if (e.empty()) return ok_status();
        auto v = eval_floats(e, env);
        if (!v) return wrap(key, v.error());
        if (v->size() != 1) return fail(key, "must be one number; it evaluates to a " + std::to_string(v->size()) + "-vector", e.loc);
        out = (*v)[0];
        return ok_status();
    }

    Status vec3(const std::string& key, const Vec3Expr& x, std::array<double, 3>& out) const {
        if (x.parts.empty()) return ok_status();
        if (x.parts.size() == 1) {
            auto v = eval_floats(x.parts[0], env);
            if (!v) return wrap(key, v.error());
            if (v->size() != 3)
                return fail(key, "must be 3 numbers; it evaluates to " + std::to_string(v->size()) + " (a vec3 param, or [x, y, z])",
                            x.parts[0].loc);
            for (size_t k = 0; k < 3; ++k) out[k] = (*v)[k];
        } else {
            for (size_t k = 0; k < 3; ++k)
                if (auto s = scalar(key + "[" + std::to_string(k) + "]", x.parts[k], out[k]); !s) return s;
        }
        for (double d : out)
            if (!std::isfinite(d)) return fail(key, "must be finite", x.loc);
        return ok_status();
    }

    SourceLoc at(const std::string& key) const { return c.keys.at(key, c.loc); }
};

} // namespace

Result<CameraValues> eval_camera(const CameraDesc& c, const SizeEnv& env) {
    CameraEval ev{c, env};
    CameraValues v;
    v.ortho = c.ortho;
    v.cube = c.cube;
    if (c.cube) v.fov = 90.0;
    for (auto [key, x, out] : {std::tuple{"eye", &c.eye, &v.eye}, {"target", &c.target, &v.target}, {"up", &c.up, &v.up}})
        if (auto s = ev.vec3(key, *x, *out); !s) return s.error();
    for (auto [key, x, out] : {std::tuple{"fov", &c.fov, &v.fov}, {"near", &c.near, &v.near}, {"far", &c.far, &v.far},
                               {"aspect", &c.aspect, &v.aspect}, {"ortho_height", &c.ortho_height, &v.ortho_height}})
        if (auto s = ev.scalar(key, *x, *out); !s) return s.error();

    if (!(v.fov > 0 && v.fov < 180)) return ev.fail("fov", "must be between 0 and 180 degrees, not " + num(v.fov), ev.at("fov"));
    if (!(v.near > 0) || std::isinf(v.near)) return ev.fail("near", "must be > 0 and finite, not " + num(v.near), ev.at("near"));
    if (!(v.far > v.near))
        return ev.fail("far", "must be greater than near (" + num(v.near) + "), not " + num(v.far), ev.at("far"));
    if (v.ortho && std::isinf(v.far))
        return ev.fail("far", "must be finite for an ortho camera (far = inf is for perspective cameras)", ev.at("far"));
    if (!(v.aspect > 0) || std::isinf(v.aspect)) return ev.fail("aspect", "must be > 0, not " + num(v.aspect), ev.at("aspect"));
    if (!(v.ortho_height > 0) || std::isinf(v.ortho_height))
        return ev.fail("ortho_height", "must be > 0, not " + num(v.ortho_height), ev.at("ortho_height"));
    if (!c.cube) {
        double d2 = 0, u2 = 0;
        for (size_t k = 0; k < 3; ++k) d2 += (v.target[k] - v.eye[k]) * (v.target[k] - v.eye[k]), u2 += v.up[k] * v.up[k];
        if (!(d2 > 0)) return ev.fail("target", "is the eye: a camera needs a direction to look in", ev.at("target"));
        if (!(u2 > 0)) return ev.fail("up", "must not be zero", ev.at("up"));
    }
    return v;
}

SizeEnv make_env(const GraphDesc& g, std::array<int, 2> view) {
    SizeEnv env;
    env.view_w = view[0];
    env.view_h = view[1];
    for (const auto& p : g.params) {
        env.params[p.name] = p.value[0];
        env.vectors[p.name].assign(p.value.begin(), p.value.begin() + p.components());
        if (!p.options.empty()) env.options[p.name] = p.options;
    }
    return env;
}

} // namespace pl::graph
