// The test models of ../shared/data (HEXREM_SHARED_DATA_DIR), shared by the test executables.
#ifndef HEXREM_TEST_SHARED_MODELS_H
#define HEXREM_TEST_SHARED_MODELS_H

#include "data_paths.h"
#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

// Every .vtk of shared/data/hexme and shared/data/mambo, sorted; empty when the folder is absent.
inline std::vector<std::string> shared_models()
{
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  for(const char* sub : {"hexme", "mambo"}) {
    const fs::path dir = fs::path(HEXREM_SHARED_DATA_DIR) / sub;
    if(!fs::exists(dir)) continue;
    for(const auto& entry : fs::directory_iterator(dir))
      if(entry.path().extension() == ".vtk") files.push_back(entry.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

#endif // HEXREM_TEST_SHARED_MODELS_H
