#version 450
layout(local_size_x = 1) in;
layout(std430) writeonly buffer Args { uint vertex_count; uint instance_count; uint first_vertex; uint first_instance; } args;
void main() {
    args.vertex_count = 6u;
    args.instance_count = 2u;
    args.first_vertex = 0u;
    args.first_instance = 0u;
}
