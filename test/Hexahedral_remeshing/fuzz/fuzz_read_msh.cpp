// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// libFuzzer target: IO::read_gmsh (.msh through the gmsh library, in its child process) then
// build_tetrahedral_mesh (see fuzz_common.h, scripts/fuzz). The bytes go through a temporary file:
// gmsh reads files only.
#include "fuzz_common.h"

#include <CGAL/Hexahedral_remeshing/IO/read_gmsh.h>

#include <fstream>
#include <unistd.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace HR = CGAL::Hexahedral_remeshing;
  static const std::string file = "/tmp/hexrem_fuzz_" + std::to_string(::getpid()) + ".msh";
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  HR::Tetrahedral_soup_3<hexrem_fuzz::Point> soup;
  try {
    HR::IO::read_gmsh(file, soup);
  } catch(const HR::Input_error&) {
    return 0;
  }
  hexrem_fuzz::build_and_check(soup);
  return 0;
}
