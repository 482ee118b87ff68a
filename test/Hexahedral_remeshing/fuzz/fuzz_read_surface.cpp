// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
//
// libFuzzer target: the surface path of read_tetrahedral_soup (OFF, OBJ, STL ASCII or binary,
// chosen from the content): CGAL's reader, the repair and orientation of the soup, the checks
// before TetGen (closed, manifold, degenerate, self-intersections), and for surfaces that pass
// them TetGen (in its child process) and build_tetrahedral_mesh (see fuzz_common.h, scripts/fuzz).
#include "fuzz_common.h"

#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>

namespace {

// The format from the content, as a user's file extension would say it.
std::string sniff(const std::string& text)
{
  std::size_t b = text.find_first_not_of(" \t\r\n");
  if(b == std::string::npos) return "off";
  const std::string head = text.substr(b, 8);
  if(head.find("OFF") != std::string::npos && head.find("OFF") < 5) return "off";
  if(head.compare(0, 5, "solid") == 0) return "stl";
  if(head[0] == 'v' || head[0] == 'f' || head[0] == '#' || head[0] == 'o' || head[0] == 'g') return "obj";
  return "stl";
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  namespace HR = CGAL::Hexahedral_remeshing;
  const std::string text(reinterpret_cast<const char*>(data), size);
  const std::string ext = sniff(text);
  const std::string source = "fuzz." + ext;
  std::vector<HR::internal::Surface_kernel::Point_3> points;
  std::vector<std::vector<std::size_t> > polygons;
  HR::Tetrahedral_soup_3<hexrem_fuzz::Point> soup;
  soup.source = source;
  try {
    HR::IO::read_surface_soup(text, ext, source, points, polygons);
    HR::internal::Checked_surface sm;
    HR::internal::surface_from_polygon_soup(points, polygons, source, sm);
    if(sm.number_of_faces() > 2000) return 0; // TetGen's time, not the readers', beyond this
    HR::tetrahedralize_checked_surface(sm, soup);
  } catch(const HR::Input_error&) {
    return 0;
  }
  hexrem_fuzz::build_and_check(soup);
  return 0;
}
