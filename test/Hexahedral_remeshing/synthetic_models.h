// Closed surfaces of the synthetic test models (OFF text), tetrahedralized by the tests with TetGen:
// a box, the L-prism (three unit cubes, one concave vertical edge), the 30-60-90 triangular prism.
#ifndef HEXREM_TEST_SYNTHETIC_MODELS_H
#define HEXREM_TEST_SYNTHETIC_MODELS_H

#include <CGAL/Hexahedral_remeshing/IO/read_tetrahedral_mesh.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

// The tetrahedral mesh of a file (boundary chords split, TetGen bound on the tet volume for surfaces).
template <class Mesh>
Mesh load_tetrahedral_mesh(const std::string& file, double max_volume = 0)
{
  Mesh m;
  CGAL::Hexahedral_remeshing::IO::read_tetrahedral_mesh(
    file, m, CGAL::Hexahedral_remeshing::parameters::split_boundary_chords(
               true, CGAL::Hexahedral_remeshing::parameters::maximum_tetrahedron_volume(max_volume)));
  return m;
}

// The tetrahedral mesh of an OFF text, written to a temporary file `name`.off.
template <class Mesh>
Mesh tetrahedral_mesh_of_off(const std::string& name, const std::string& text, double max_volume)
{
  const std::string off = (std::filesystem::temp_directory_path() / (name + ".off")).string();
  {
    std::ofstream out(off);
    out.precision(17);
    out << text;
  }
  Mesh m = load_tetrahedral_mesh<Mesh>(off, max_volume);
  std::remove(off.c_str());
  return m;
}

// The box [0,a] x [0,b] x [0,c].
inline std::string box_off(double a, double b, double c)
{
  std::ostringstream os;
  os.precision(17);
  os << "OFF\n8 12 0\n0 0 0\n" << a << " 0 0\n" << a << " " << b << " 0\n0 " << b << " 0\n"
     << "0 0 " << c << "\n" << a << " 0 " << c << "\n" << a << " " << b << " " << c << "\n0 " << b << " " << c << "\n"
     << "3 0 2 1\n3 0 3 2\n3 4 5 6\n3 4 6 7\n3 0 1 5\n3 0 5 4\n3 1 2 6\n3 1 6 5\n3 2 3 7\n3 2 7 6\n3 3 0 4\n3 3 4 7\n";
  return os.str();
}

// The L of the unit squares (0,0), (1,0), (0,1) extruded from z = 0 to z = 1.
inline std::string l_prism_off()
{
  const double P[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  std::ostringstream os;
  os << "OFF\n12 20 0\n";
  for(int z = 0; z < 2; ++z)
    for(const auto& p : P) os << p[0] << " " << p[1] << " " << z << "\n";
  // bottom (outward -z) and top, as fans of the L split into convex pieces: (0,1,2,3),(0,3,4,5)
  os << "3 0 2 1\n3 0 3 2\n3 0 4 3\n3 0 5 4\n";
  os << "3 6 7 8\n3 6 8 9\n3 6 9 10\n3 6 10 11\n";
  for(int i = 0; i < 6; ++i) {
    const int j = (i + 1) % 6;
    os << "3 " << i << " " << j << " " << j + 6 << "\n3 " << i << " " << j + 6 << " " << i + 6 << "\n";
  }
  return os.str();
}

// The triangle (0,0), (1,0), (0,1/sqrt(3)) (angles 90, 30, 60 degrees) extruded from z = 0 to z = 1.
inline std::string prism_30_60_90_off()
{
  const double c = 1.0 / std::sqrt(3.0);
  std::ostringstream os;
  os.precision(17);
  os << "OFF\n6 8 0\n0 0 0\n1 0 0\n0 " << c << " 0\n0 0 1\n1 0 1\n0 " << c << " 1\n"
     << "3 0 2 1\n3 3 4 5\n3 0 1 4\n3 0 4 3\n3 1 2 5\n3 1 5 4\n3 2 0 3\n3 2 3 5\n";
  return os.str();
}

// A U-channel: the rectangle [0,2] x [0,1] with the slot [1 - w/2, 1 + w/2] x [0.4, 1] cut out,
// extruded from z = 0 to z = 1. The slot's two bottom edges are concave (valence 3), w apart.
inline std::string u_channel_off(double w)
{
  const double a = 1 - w / 2, b = 1 + w / 2;
  const double P[8][2] = {{0, 0}, {2, 0}, {2, 1}, {b, 1}, {b, 0.4}, {a, 0.4}, {a, 1}, {0, 1}};
  // the cap as triangles of the (counter-clockwise) polygon
  const int T[6][3] = {{0, 1, 4}, {0, 4, 5}, {1, 2, 4}, {2, 3, 4}, {0, 5, 7}, {5, 6, 7}};
  std::ostringstream os;
  os.precision(17);
  os << "OFF\n16 28 0\n";
  for(int z = 0; z < 2; ++z)
    for(const auto& p : P) os << p[0] << " " << p[1] << " " << z << "\n";
  for(const auto& t : T) os << "3 " << t[0] << " " << t[2] << " " << t[1] << "\n";
  for(const auto& t : T) os << "3 " << t[0] + 8 << " " << t[1] + 8 << " " << t[2] + 8 << "\n";
  for(int i = 0; i < 8; ++i) {
    const int j = (i + 1) % 8;
    os << "3 " << i << " " << j << " " << j + 8 << "\n3 " << i << " " << j + 8 << " " << i + 8 << "\n";
  }
  return os.str();
}

#endif // HEXREM_TEST_SYNTHETIC_MODELS_H
