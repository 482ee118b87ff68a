// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_COMPLEX_QUANTIZATION_H
#define CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_COMPLEX_QUANTIZATION_H

#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/dof_reduction.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/motorcycle_complex/complex_quantizer.h>
#include <CGAL/Hexahedral_remeshing/internal/integer_grid_map/seamless_map.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <algorithm>
#include <array>
#include <cstdint>
#include <memory>
#include <vector>

namespace CGAL {
namespace Hexahedral_remeshing {
namespace internal {

// The corner parameters of the reduced map problem x = P y + x0 as functions of y.
class Reduced_map_forms : public motorcycle::Map_forms
{
public:
  typedef Eigen::SparseMatrix<double, Eigen::RowMajor> Row_matrix;

  Reduced_map_forms(const Row_matrix& P, const Eigen::VectorXd& x0, const std::vector<std::array<std::uint32_t, 4> >& tets)
    : m_P(P), m_x0(x0), m_tets(tets)
  {}

  Linear_form corner(std::uint32_t t, std::uint32_t v, int axis) const override
  {
    const int c = int(std::find(m_tets[t].begin(), m_tets[t].end(), v) - m_tets[t].begin());
    const Eigen::Index i = Eigen::Index(map_scalar(t, c, axis));
    Linear_form f;
    f.constant = m_x0[i];
    for(Row_matrix::InnerIterator it(m_P, i); it; ++it)
      if(it.value() != 0) f.terms.emplace_back(it.col(), it.value());
    std::sort(f.terms.begin(), f.terms.end());
    return f;
  }

private:
  const Row_matrix& m_P;
  const Eigen::VectorXd& m_x0;
  const std::vector<std::array<std::uint32_t, 4> >& m_tets;
};

// The motorcycle complex of the seamless map y_s (issue 27 step 2) with its block extents as functions
// of the variables, traced only when the seamless map is injective, within `seconds` and a size limit;
// null (with the report saying why) otherwise.
template <class Traits>
std::unique_ptr<motorcycle::Motorcycle_complex>
seamless_map_complex(const Tetrahedral_mesh_3<Traits>& mesh, const Eigen::SparseMatrix<double, Eigen::RowMajor>& P,
                     const Eigen::VectorXd& x0, const Seamless_map& seamless, double seconds,
                     motorcycle::Motorcycle_complex_report& report)
{
  if(!seamless.success || !seamless.folds.empty()) {
    report.reason = "the seamless map is not injective";
    return nullptr;
  }
  std::vector<std::array<double, 3> > positions(mesh.number_of_vertices());
  for(std::size_t v = 0; v < positions.size(); ++v)
    for(int k = 0; k < 3; ++k) positions[v][std::size_t(k)] = CGAL::to_double(mesh.point(typename Tetrahedral_mesh_3<Traits>::Index(v))[k]);
  std::vector<std::array<std::uint32_t, 4> > tets(mesh.number_of_tetrahedra());
  for(std::size_t t = 0; t < tets.size(); ++t)
    for(int c = 0; c < 4; ++c) tets[t][std::size_t(c)] = std::uint32_t(mesh.tetrahedron_vertices(typename Tetrahedral_mesh_3<Traits>::Index(t))[c]);
  std::vector<std::array<Eigen::Vector3d, 4> > parameters;
  corner_parameters(P * seamless.y + x0, parameters);
  const Reduced_map_forms forms(P, x0, tets);
  // up to 20 times the tetrahedra (a wall across the part splits about 15 per tetrahedron it crosses),
  // and 2 million in all (about 2 GB)
  const double growth = (std::min)(20.0, 2e6 / double((std::max)(std::size_t(1), tets.size())));
  std::unique_ptr<motorcycle::Motorcycle_complex> mc(
    new motorcycle::Motorcycle_complex(motorcycle::trace_motorcycle_complex(positions, tets, parameters, growth, &forms, seconds)));
  report = mc->report;
  return mc;
}

} // namespace internal
} // namespace Hexahedral_remeshing
} // namespace CGAL

#endif // CGAL_HEXAHEDRAL_REMESHING_INTERNAL_INTEGER_GRID_MAP_COMPLEX_QUANTIZATION_H
