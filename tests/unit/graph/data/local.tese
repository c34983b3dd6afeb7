#version 450
// Stub for tests/unit/graph: validation only checks that the file exists; it is never compiled.
