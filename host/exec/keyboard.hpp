// Keyboard state as shaders see it in `frame.keys`: Shadertoy's keyboard texture (256 keys x 3
// rows: held down, pressed this frame, toggled by each press), indexed by the JavaScript keyCode
// Shadertoy uses (65 = A, 32 = space, 37..40 = arrows), one bit each. `run` fills it from the
// window, a [[test]]'s `keys` holds keys down from the first frame, everything else sees zeros.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace pl::exec {

struct KeyboardState {
    enum Row : int { down = 0, pressed = 1, toggled = 2 };
    // Row r, key k is bit k % 32 of word r * 8 + k / 32: the layout of `uvec4 keys[6]`.
    std::array<uint32_t, 24> bits{};

    void set(Row r, int key, bool on) {
        if (key < 0 || key > 255) return;
        uint32_t& w = bits[static_cast<std::size_t>(r * 8 + key / 32)];
        const uint32_t m = 1u << (key % 32);
        w = on ? (w | m) : (w & ~m);
    }
    // Every key of row r off (the "pressed" row lasts one frame).
    void clear(Row r) {
        for (std::size_t i = 0; i < 8; ++i) bits[static_cast<std::size_t>(r) * 8 + i] = 0;
    }
    bool get(Row r, int key) const {
        return key >= 0 && key <= 255 && (bits[static_cast<std::size_t>(r * 8 + key / 32)] >> (key % 32)) & 1u;
    }
};

// `keys` held down from frame 0 on: down every frame, pressed on frame 0 only, toggled once.
inline KeyboardState held_keys(const std::vector<int>& keys, int frame) {
    KeyboardState s;
    for (int k : keys) {
        s.set(KeyboardState::down, k, true);
        s.set(KeyboardState::pressed, k, frame == 0);
        s.set(KeyboardState::toggled, k, true);
    }
    return s;
}

} // namespace pl::exec
