// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// Driver that runs a fuzz target on files or on every file of directories, without libFuzzer:
// the ctest entries fuzz_replay_* run the seed corpus and the regression fixtures through the
// targets with the ordinary (and the sanitizer) build.
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

int main(int argc, char** argv)
{
  namespace fs = std::filesystem;
  std::vector<fs::path> files;
  for(int i = 1; i < argc; ++i) {
    const fs::path p(argv[i]);
    if(fs::is_directory(p)) {
      for(const auto& entry : fs::directory_iterator(p))
        if(entry.is_regular_file()) files.push_back(entry.path());
    } else {
      files.push_back(p);
    }
  }
  for(const fs::path& f : files) {
    std::ifstream in(f, std::ios::binary);
    if(!in) { std::fprintf(stderr, "cannot read %s\n", f.string().c_str()); return 1; }
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    LLVMFuzzerTestOneInput(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  std::printf("%zu inputs replayed\n", files.size());
  return files.empty() ? 1 : 0;
}
