// A shared object standing in for a mesh import module of another version
// (passes/mesh/reader/import_entry.h): it exports an entry point under an
// older name, and mdlc must refuse it when it opens it (cli_test.cc).
extern "C" __attribute__((visibility("default"))) int mdlc_mesh_import_v0() { return 0; }
