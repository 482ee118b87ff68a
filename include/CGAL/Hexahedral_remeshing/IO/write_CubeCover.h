// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_CUBECOVER_H
#define CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_CUBECOVER_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/IO/write_MEDIT.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>
#include <CGAL/Hexahedral_remeshing/internal/octahedral_group.h>

#include <Eigen/Dense>

#include <array>
#include <cstdio>
#include <string>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace IO {

/// \ingroup PkgHexahedralRemeshingRef
/// The CubeCover encoding `(p1, p2, p3)` of a matching (an element of the octahedral group as
/// stored in `Matchings::face_matching`, 0 to 23): vector `i` of the first tetrahedron times the
/// sign of `p_i` is vector `|p_i|` of the second.
inline std::array<int, 3> CubeCover_permutation(int matching)
{
  if(matching < 0 || matching >= 24) throw Error("CubeCover_permutation: invalid matching " + std::to_string(matching));
  const Eigen::Matrix3d& G = internal::octahedral_group().matrix(matching);
  std::array<int, 3> p{{0, 0, 0}};
  for(int i = 0; i < 3; ++i) {
    int r = 0;
    G.col(i).cwiseAbs().maxCoeff(&r);
    p[std::size_t(i)] = (G(r, i) > 0 ? 1 : -1) * (r + 1);
  }
  return p;
}

/// \ingroup PkgHexahedralRemeshingRef
/// Writes the frames in CubeCover's `.fra` format (three vectors per tetrahedron; see
/// `write_CubeCover()` for the format).
/// \throws Error if the file cannot be written.
inline void write_CubeCover_frames(const std::string& filename, const std::vector<Eigen::Matrix3d>& frames)
{
  write_file_atomically(filename, [&](std::ostream& out) {
    out << "FRA 1\n" << frames.size() << " 3 1\n";
    for(const Eigen::Matrix3d& E : frames)
      for(int c = 0; c < 3; ++c) out << E(0, c) << " " << E(1, c) << " " << E(2, c) << "\n";
  });
}

/// \ingroup PkgHexahedralRemeshingRef
/// Writes the matchings in CubeCover's `.perm` format (one line per interior face whose matching
/// is not the identity; see `write_CubeCover()` for the format).
/// \throws Error if the file cannot be written or `matchings` does not have one entry per face.
template <class Traits>
void write_CubeCover_matchings(const std::string& filename, const Tetrahedral_mesh_3<Traits>& mesh,
                               const Matchings& matchings)
{
  typedef typename Tetrahedral_mesh_3<Traits>::Index Index;
  if(matchings.face_matching.size() != mesh.number_of_faces())
    throw Error(filename + ": " + std::to_string(matchings.face_matching.size()) + " matchings for " +
                std::to_string(mesh.number_of_faces()) + " faces");
  std::vector<Index> listed;
  for(Index f = 0; f < mesh.number_of_faces(); ++f) {
    const int g = matchings.face_matching[f];
    if(mesh.is_boundary_face(f) || g < 0) continue;
    if(g != internal::Octahedral_group::identity_index) listed.push_back(f);
  }
  write_file_atomically(filename, [&](std::ostream& out) {
    out << "PERM 1\n" << mesh.number_of_tetrahedra() << " " << listed.size() << " 3\n";
    for(Index f : listed) {
      const auto& ft = mesh.face_tetrahedra(f);
      const std::array<int, 3> p = CubeCover_permutation(matchings.face_matching[f]);
      out << ft[0] << " " << ft[1] << " " << p[0] << " " << p[1] << " " << p[2] << "\n";
    }
  });
}

/// \ingroup PkgHexahedralRemeshingRef
/// Writes `prefix.mesh` (the tetrahedral mesh, `write_MEDIT()`), `prefix.fra` (the frames) and
/// `prefix.perm` (the matchings), the three files CubeCover reads. If one file cannot be written,
/// the ones already written by this call are removed.
///
/// Files for CubeCover (https://github.com/evouga/CubeCover, seamless and integer-grid
/// parametrization of a frame field on a tetrahedral mesh), so that our fields can be fed to it
/// (`readFrameField()` then `cubeCover()` with `AssignmentHandling::AH_USEPROVIDED`).
///
/// The formats were read from CubeCover's code (repository evouga/CubeCover): the reader
/// `readFrameField()` in `src/ReadFrameField.cpp`, the documentation of `cubeCover()` in
/// `src/CubeCover.h`, `parseFromPerm()` and the action of a group element in
/// `src/AssignmentGroup.cpp`, the face look-up of `fromFramesAndAssignments()` in
/// `src/FrameField.cpp`, CubeCover's own writer in `src/WriteFrameFIeld.cpp`, and its `.mesh`
/// reader `readMESH()` in `src/readMeshFixed.h`. The conventions matched:
/// - **Tetrahedra and vertices**: CubeCover numbers the tetrahedra in the order of the
///   `Tetrahedra` block of the `.mesh` file it reads (its vertex indices are the file's 1-based
///   indices minus one). `write_CubeCover()` therefore also writes that `.mesh` file, with
///   `write_MEDIT()`: tetrahedron `t` and vertex `v` there are `t` and `v` of our mesh, the numbering
///   used in the `.fra` and `.perm` files (and in `write_VTK()` / `write_VTK_frame_field()`).
/// - **`.fra`**: the header `FRA 1`, then `n 3 1` (number of tetrahedra, vectors per frame, a type
///   field that the reader ignores; CubeCover's writer puts 1), then three lines `x y z` per
///   tetrahedron in tetrahedron order: its three frame vectors in ambient coordinates (our axes,
///   the columns of the frame matrix, in order).
/// - **`.perm`**: the header `PERM 1`, then `n m 3` (tetrahedra, number of listed faces, vectors per
///   frame), then one line `t1 t2 p1 p2 p3` per listed face, with 0-based tetrahedra. `p_i` is in
///   {±1, ±2, ±3}: vector `i` of the frame of `t1`, multiplied by the sign of `p_i`, matches vector
///   `|p_i|` of the frame of `t2` (CubeCover's `parseFromPerm()`: target `|p|-1`, sign of `p`).
/// - **Faces are not numbered**: CubeCover finds the face of a line from the pair `(t1, t2)`, in
///   either order (it inverts the permutation when the pair is reversed), so its own face numbering
///   never appears in the file. We write `t1, t2 = mesh.face_tetrahedra(f)` and, like CubeCover's
///   writer, list only the interior faces whose matching is not the identity (a face not listed
///   is the identity). Boundary faces are never listed.
/// - **Encoding of our matchings**: our matching `g_f` of face `f` with `(t0, t1) =
///   mesh.face_tetrahedra(f)` satisfies `E_t0 ~ E_t1 G` (`G` the signed permutation matrix of
///   `g_f`), i.e. column `i` of `E_t0` is `s E_t1 e_r` where column `i` of `G` is `s e_r`: so
///   `p_i = s (r + 1)`.
///
/// Not matched: the example file `meshes/tetrahedron_100.perm` of the CubeCover repository uses an
/// older 0-based encoding that the current reader rejects; we follow the reader.
///
/// \param prefix path and base name of the three files
/// \param mesh the mesh
/// \param frames one frame per tetrahedron
/// \param matchings the matchings of the frames (`compute_matchings()`, or those kept by
///        `realign_frame_field()`)
/// \throws Error if a file cannot be written or the sizes do not match the mesh.
template <class Traits>
void write_CubeCover(const std::string& prefix, const Tetrahedral_mesh_3<Traits>& mesh,
                     const std::vector<Eigen::Matrix3d>& frames, const Matchings& matchings)
{
  if(frames.size() != mesh.number_of_tetrahedra())
    throw Error(prefix + ".fra: " + std::to_string(frames.size()) + " frames for " +
                std::to_string(mesh.number_of_tetrahedra()) + " tetrahedra");
  std::vector<std::string> written;
  try {
    write_MEDIT(prefix + ".mesh", mesh);
    written.push_back(prefix + ".mesh");
    write_CubeCover_frames(prefix + ".fra", frames);
    written.push_back(prefix + ".fra");
    write_CubeCover_matchings(prefix + ".perm", mesh, matchings);
  } catch(...) {
    for(const std::string& f : written) std::remove(f.c_str());
    throw;
  }
}

} // namespace IO
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_IO_WRITE_CUBECOVER_H
