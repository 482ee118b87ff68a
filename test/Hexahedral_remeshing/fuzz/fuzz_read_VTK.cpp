// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// libFuzzer target: IO::read_VTK then build_tetrahedral_mesh (see fuzz_common.h, scripts/fuzz).
#include "fuzz_common.h"

#include <CGAL/Hexahedral_remeshing/IO/read_VTK.h>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  return hexrem_fuzz::fuzz_one_input(data, size, "fuzz.vtk",
    [](const std::string& text, const std::string& source, CGAL::Hexahedral_remeshing::Tetrahedral_soup_3<hexrem_fuzz::Point>& soup) {
      CGAL::Hexahedral_remeshing::IO::read_VTK(text, source, soup);
    });
}
