#version 450
// Second half: add the tiles up (three 1x1 results).
//   rmse:   RMSE against the reference (trilinear, hardware 16x, shader, pixel count)
//   means:  (reference, trilinear, hardware, shader)
//   ratios: what the test checks (RMSE hardware / trilinear, RMSE shader / trilinear,
//           mean hardware / reference, mean shader / reference)
layout(location = 0) out vec4 rmse_out;
layout(location = 1) out vec4 means_out;
layout(location = 2) out vec4 ratios;
uniform sampler2D tiles_sq;
uniform sampler2D tiles_sum;
void main() {
    ivec2 size = textureSize(tiles_sq, 0);
    vec4 sq = vec4(0.0), sum = vec4(0.0);
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            sq += texelFetch(tiles_sq, ivec2(x, y), 0);
            sum += texelFetch(tiles_sum, ivec2(x, y), 0);
        }
    float n = max(sq.w, 1.0);
    vec3 rmse = sqrt(sq.xyz / n);
    vec4 mean = sum / n;
    rmse_out = vec4(rmse, sq.w);
    means_out = mean;
    ratios = vec4(rmse.y / rmse.x, rmse.z / rmse.x, mean.z / mean.x, mean.w / mean.x);
}
