// Where the tests find their data. The paths are defined in a small generated source of the build tree
// (data_paths.cpp.in), not passed as -D definitions: the test executables' compile commands then carry
// no absolute path, so that ccache (CCACHE_BASEDIR=the clone) reuses them from another clone of the
// same sources; with the paths in -D every test was compiled again on each fresh clone.
#ifndef HEXREM_TEST_DATA_PATHS_H
#define HEXREM_TEST_DATA_PATHS_H

namespace hexrem_test {
extern const char* const test_data_dir;     // test/Hexahedral_remeshing/data
extern const char* const example_data_dir;  // examples/Hexahedral_remeshing/data
extern const char* const shared_data_dir;   // ../shared/data (may be absent: tests that need it skip)
}  // namespace hexrem_test

#define HEXREM_TEST_DATA_DIR ::hexrem_test::test_data_dir
#define HEXREM_EXAMPLE_DATA_DIR ::hexrem_test::example_data_dir
#define HEXREM_SHARED_DATA_DIR ::hexrem_test::shared_data_dir

#endif
