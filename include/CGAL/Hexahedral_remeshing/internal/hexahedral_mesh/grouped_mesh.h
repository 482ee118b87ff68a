// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_MESH_GROUPED_MESH_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_MESH_GROUPED_MESH_H

#include <CGAL/Hexahedral_remeshing/Hexahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/hexahedral_boundary_groups.h>

#include <cctype>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// A file that refers to missing vertices is worse than no file: every writer rejects such a mesh first.
inline void check_hexahedra_in_range(const std::string& filename, const Hexahedral_mesh_3& hexes)
{
  for(std::size_t h = 0; h < hexes.hexahedra.size(); ++h)
    for(auto v : hexes.hexahedra[h])
      if(v >= hexes.points.size())
        throw Error(filename + ": hexahedron " + std::to_string(h) + " has vertex index " + std::to_string(v) +
                    " out of range (" + std::to_string(hexes.points.size()) + " vertices)");
}

// The mesh a solver-format writer writes: `hexes` itself when it has its boundary groups, else a
// copy grouped by its own sharp edges (a file for a solver always names its boundary).
class Grouped_mesh
{
public:
  explicit Grouped_mesh(const Hexahedral_mesh_3& hexes) : m_mesh(&hexes)
  {
    if(!hexes.boundary_quadrilaterals.empty() || hexes.hexahedra.empty()) return;
    m_own.reset(new Hexahedral_mesh_3(hexes));
    compute_hexahedral_boundary_groups(*m_own);
    m_mesh = m_own.get();
  }
  const Hexahedral_mesh_3& mesh() const { return *m_mesh; }

  // The boundary quads of each patch, as indices into `boundary_quadrilaterals`, by increasing patch.
  std::map<int, std::vector<std::size_t> > quads_by_patch() const
  {
    std::map<int, std::vector<std::size_t> > groups;
    for(std::size_t i = 0; i < m_mesh->boundary_quadrilaterals.size(); ++i)
      groups[m_mesh->boundary_quadrilaterals[i].patch].push_back(i);
    return groups;
  }
  // The feature edges of each curve, by increasing curve.
  std::map<int, std::vector<std::size_t> > edges_by_curve() const
  {
    std::map<int, std::vector<std::size_t> > groups;
    for(std::size_t i = 0; i < m_mesh->feature_edges.size(); ++i) groups[m_mesh->feature_edges[i].curve].push_back(i);
    return groups;
  }

  // The name of a patch: its given name made a valid identifier of every solver format (letters,
  // digits and '_', starting with a letter, at most 64 characters), else `patch_<id>`.
  // The name of a patch's group: its given name made an identifier, else `patch_<id>`. Patches of one
  // name (a physical group of several surfaces) form one group.
  std::string patch_name(int patch) const
  {
    for(const auto& pn : m_mesh->patch_names)
      if(pn.first == patch) {
        const std::string s = identifier(pn.second);
        if(!s.empty()) return s;
      }
    return patch < 0 ? std::string("patch_unknown") : "patch_" + std::to_string(patch);
  }
  // The boundary quads of each named group (indices into `boundary_quadrilaterals`), by name.
  std::map<std::string, std::vector<std::size_t> > quads_by_name() const
  {
    std::map<std::string, std::vector<std::size_t> > groups;
    for(const auto& g : quads_by_patch()) {
      auto& quads = groups[patch_name(g.first)];
      quads.insert(quads.end(), g.second.begin(), g.second.end());
    }
    return groups;
  }
  // A name made an identifier of every solver format, or "" if it cannot be one.
  static std::string identifier(const std::string& name)
  {
    std::string s;
    for(unsigned char c : name) s += std::isalnum(c) ? char(c) : '_';
    const bool ok = !s.empty() && std::isalpha((unsigned char)s[0]) && s.size() <= 64 && s.compare(0, 6, "curve_") != 0 &&
                    s.compare(0, 6, "patch_") != 0 && s != "part" && s != "PART";
    return ok ? s : std::string();
  }
  static std::string curve_name(int curve)
  {
    return curve < 0 ? std::string("curve_unknown") : "curve_" + std::to_string(curve);
  }

private:
  const Hexahedral_mesh_3* m_mesh;
  std::unique_ptr<Hexahedral_mesh_3> m_own;
};

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_HEXAHEDRAL_MESH_GROUPED_MESH_H
