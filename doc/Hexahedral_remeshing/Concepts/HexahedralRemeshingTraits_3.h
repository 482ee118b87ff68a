/*!
\ingroup PkgHexahedralRemeshingConcepts
\cgalConcept

The concept `HexahedralRemeshingTraits_3` gives the geometric types and predicates that the package
uses on a tetrahedral mesh: the orientation of four points, which decides how tetrahedra and boundary
triangles are oriented, and the class of a boundary dihedral angle, which gives the valence that a
frame field aligned with the boundary normals imposes on a boundary edge.

Both predicates must be exact: the topology built by `CGAL::Hexahedral_remeshing::Tetrahedral_mesh_3`
and the default valences of the boundary edges depend on them, and the valence of an edge whose
dihedral angle is exactly an odd multiple of \f$ \pi/4 \f$ (a 45 degree wedge, for instance) must not
depend on rounding errors.

\cgalHasModel{`CGAL::Hexahedral_remeshing::Hexahedral_remeshing_traits_3`}

\sa `CGAL::Hexahedral_remeshing::Tetrahedral_mesh_3`
*/
class HexahedralRemeshingTraits_3
{
public:

/// \name Types
/// @{

/*!
Number type of the coordinates. Its values must convert exactly to `double`
(as with `CGAL::Exact_predicates_inexact_constructions_kernel`).
*/
typedef unspecified_type FT;

/*!
Point type, with coordinates of type `FT`.
*/
typedef unspecified_type Point_3;

/*!
Vector type, with coordinates of type `FT`. It is the type of the difference of two `Point_3`.
*/
typedef unspecified_type Vector_3;

/*!
Functor deciding exactly the orientation of four points, a model of the kernel concept
`Kernel::Orientation_3`
(<a href="https://doc.cgal.org/5.5.1/Kernel_23/classKernel_1_1Orientation__3.html">CGAL manual</a>).

It provides:

`CGAL::Orientation operator()(const Point_3& p, const Point_3& q, const Point_3& r, const Point_3& s)`,

which returns the sign of the determinant of `(q - p, r - p, s - p)`: `CGAL::POSITIVE` if the
tetrahedron `(p, q, r, s)` is positively oriented (`s` lies on the side of the plane `pqr` towards
which \f$ (q - p) \times (r - p) \f$ points), `CGAL::NEGATIVE` if it is negatively oriented, and
`CGAL::COPLANAR` if the four points are coplanar.
*/
typedef unspecified_type Orientation_3;

/*!
Functor computing exactly the class of the dihedral angle at a boundary edge.

It provides:

`int operator()(const Point_3& p, const Point_3& q, const Point_3& a, const Point_3& b)`.

The triangles `(p, q, a)` and `(q, p, b)` are the first and the second boundary triangle
incident to the edge `pq`, both oriented outward (counter-clockwise seen from outside the mesh), so that
`p -> q` is the half-edge of the first triangle, the edge \f$ e_{ij} \f$ of the paper with
\f$ i \f$ the first triangle and \f$ j \f$ the second one.
With \f$ n_i = (q - p) \times (a - p) \f$ and \f$ n_j = (p - q) \times (b - q) \f$ their outward normals
and \f$ e = q - p \f$, the dihedral angle in \f$ [0, 2\pi] \f$ is
\f[ \varphi = \pi - \operatorname{atan2}\left(\left\langle n_i \times n_j, \frac{e}{|e|} \right\rangle, \langle n_i, n_j \rangle\right), \f]
which is \f$ \pi \f$ for coplanar triangles, \f$ \pi/2 \f$ at a convex right angle (an edge of a cube)
and \f$ 3\pi/2 \f$ at a concave right angle.

The functor returns \f$ \operatorname{round}(2\varphi/\pi) \f$, an integer in `0..4`, decided exactly
(without trigonometry), where a tie, that is an angle that is exactly an odd multiple of \f$ \pi/4 \f$, is rounded
up to the larger class.

\pre The two triangles are not degenerate.
*/
typedef unspecified_type Dihedral_class_3;

/// @}

/// \name Operations
/// @{

/*!
Returns an instance of the orientation functor.
*/
Orientation_3 orientation_3_object() const;

/*!
Returns an instance of the dihedral class functor.
*/
Dihedral_class_3 dihedral_class_3_object() const;

/// @}

}; /* end HexahedralRemeshingTraits_3 */
