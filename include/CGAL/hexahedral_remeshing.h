// Copyright (c) 2026 The Hexahedral_remeshing project.
// SPDX-License-Identifier: GPL-3.0-or-later
// Author(s) : Hexahedral_remeshing developers
#ifndef CGAL_HEXAHEDRAL_REMESHING_H
#define CGAL_HEXAHEDRAL_REMESHING_H

/// \file hexahedral_remeshing.h
/// Umbrella header of the Hexahedral_remeshing package: includes every public header. The whole
/// frame-field pipeline is `CGAL::Hexahedral_remeshing::compute_frame_field_pipeline()`.

#include <CGAL/Hexahedral_remeshing/Hexahedral_remeshing_traits_3.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_mesh_3.h>
#include <CGAL/Hexahedral_remeshing/Tetrahedral_soup_3.h>
#include <CGAL/Hexahedral_remeshing/boundary_dihedral_angles.h>
#include <CGAL/Hexahedral_remeshing/boundary_direction_constraints.h>
#include <CGAL/Hexahedral_remeshing/boundary_edge_valences.h>
#include <CGAL/Hexahedral_remeshing/boundary_triangle_normals.h>
#include <CGAL/Hexahedral_remeshing/build_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/exceptions.h>
#include <CGAL/Hexahedral_remeshing/frame_field.h>
#include <CGAL/Hexahedral_remeshing/frame_field_pipeline.h>
#include <CGAL/Hexahedral_remeshing/mesh_statistics.h>
#include <CGAL/Hexahedral_remeshing/parameters.h>
#include <CGAL/Hexahedral_remeshing/realign_frame_field.h>
#include <CGAL/Hexahedral_remeshing/singularity_graph.h>
#include <CGAL/Hexahedral_remeshing/tetrahedral_soup_from_c3t3.h>
#include <CGAL/Hexahedral_remeshing/tetrahedralize_surface.h>
#include <CGAL/Hexahedral_remeshing/IO/edge_valences.h>
#include <CGAL/Hexahedral_remeshing/IO/read_MEDIT.h>
#include <CGAL/Hexahedral_remeshing/IO/read_VTK.h>
#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>
#include <CGAL/Hexahedral_remeshing/IO/write_CubeCover.h>
#include <CGAL/Hexahedral_remeshing/IO/write_MEDIT.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK_boundary.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK_frame_field.h>
#include <CGAL/Hexahedral_remeshing/IO/write_VTK_polylines.h>

#endif // CGAL_HEXAHEDRAL_REMESHING_H
