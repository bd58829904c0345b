/*!
\ingroup PkgProgressiveEmbeddingConcepts
\cgalConcept

The concept `ProgressiveEmbeddingTraits_2` describes the number type, the 2D objects,
the predicates and the constructions with which the algorithms of this package compute
and certify planar embeddings (the uv coordinates of a mesh).

Every algorithm of the package is written once against this concept, so that the same
code runs with `double` coordinates, with exact rationals, and with multiple-precision
floating-point numbers. The only requirement that a %CGAL `Kernel` does not fulfill by itself
is `Exact_orientation_2`: an orientation predicate that is exact for the number type `FT`,
whatever it is. With `CGAL::Exact_predicates_inexact_constructions_kernel` and with exact
kernels, `Orientation_2` is already exact; with `CGAL::Simple_cartesian<CGAL::Gmpfr>` or
`CGAL::Simple_cartesian<double>` it is not.

The number type `FT` must be a field type: `float`, `double`, an exact rational type
(`CGAL::Gmpq`, `CGAL::Lazy_exact_nt<...>`, `boost::multiprecision` rationals), or `CGAL::Gmpfr`.
A ring such as `CGAL::Mpzf` is not suitable, because the algorithms divide (linear solves,
barycenters, line searches). `long double` is not supported: the exact predicates decide signs
in double or in rationals, and a `long double` would be rounded to double there. The default
traits and every function of the package reject these types at compile time with a message
naming the supported ones.

A model is passed to the functions of the package with the named parameter
`CGAL::parameters::geom_traits()` (`tutte_embedding()`, `check_embedding()`,
`measure_distortion()`); by default they use
`CGAL::Progressive_embedding::Progressive_embedding_traits_2<K>` with `K` the kernel of the uv
map's point type. The certificate decides every sign with `Exact_orientation_2` and exact
comparisons of coordinates, so a model whose `Exact_orientation_2` is exact makes the certificate
exact.

\cgalHasModel `CGAL::Progressive_embedding::Progressive_embedding_traits_2<K>`, for any %CGAL `Kernel` `K`
whose `FT` is one of the types above.

\sa `CGAL::Progressive_embedding::Progressive_embedding_traits_2<K>`
*/
class ProgressiveEmbeddingTraits_2
{
public:

/// \name Types
/// @{

/*!
The field number type of the coordinates. It must be a model of `FieldNumberType`.
*/
typedef unspecified_type FT;

/*!
The 2D point type: the value type of uv maps.
*/
typedef unspecified_type Point_2;

/*!
The 2D vector type.
*/
typedef unspecified_type Vector_2;

/// @}

/// \name Predicates
/// @{

/*!
A function object providing
`CGAL::Orientation operator()(const Point_2& p, const Point_2& q, const Point_2& r)`,
which returns `CGAL::LEFT_TURN`, `CGAL::RIGHT_TURN` or `CGAL::COLLINEAR` depending on the
position of `r` relative to the oriented line through `p` and `q`.
It may be inexact for some number types (e.g. it rounds with `CGAL::Gmpfr`);
the algorithms use it only where an inexact answer cannot invalidate a result.

A model of `Kernel::Orientation_2`.
*/
typedef unspecified_type Orientation_2;

/*!
A function object providing
`CGAL::Orientation operator()(const Point_2& p, const Point_2& q, const Point_2& r)`
with the same meaning as `Orientation_2`, but whose result is the exact sign of the
orientation determinant of the three points as they are represented in `FT`,
for every supported number type and at every magnitude of the coordinates (values beyond the range
of `double`, such as rationals of size 2^1100 or 2^-1100, included).
The validity certificate (`check_embedding()`) and every test deciding whether a
triangle of an embedding is positively oriented use this predicate.
*/
typedef unspecified_type Exact_orientation_2;

/// @}

/// \name Constructions
/// @{

/*!
A function object providing
`Point_2 operator()(const Point_2& p, const Point_2& q)`, which returns the midpoint of `p` and `q`.

A model of `Kernel::ConstructMidpoint_2`.
*/
typedef unspecified_type Construct_midpoint_2;

/*!
A function object providing
`Point_2 operator()(const Point_2& p1, const FT& w1, const Point_2& p2, const FT& w2)`,
`Point_2 operator()(const Point_2& p1, const FT& w1, const Point_2& p2)` (the weight of `p2` is `1 - w1`) and
`Point_2 operator()(const Point_2& p1, const FT& w1, const Point_2& p2, const FT& w2, const Point_2& p3, const FT& w3)`,
which return the barycenter of the weighted points; the weights must not sum to zero.
It is used for affine combinations of points (e.g. the positions tried by the line searches).

A model of `Kernel::ConstructBarycenter_2`.
*/
typedef unspecified_type Construct_barycenter_2;

/*!
A function object providing
`FT operator()(const Point_2& p, const Point_2& q, const Point_2& r)`,
which returns the signed area of the triangle `(p, q, r)`: positive if the triangle is
counterclockwise. Its sign is not guaranteed to be exact: decide orientations with
`Exact_orientation_2`.

A model of `Kernel::ComputeArea_2`.
*/
typedef unspecified_type Compute_area_2;

/*!
A function object providing
`Vector_2 operator()(const Point_2& p, const Point_2& q)`, which returns the vector `q - p`.

A model of `Kernel::ConstructVector_2`.
*/
typedef unspecified_type Construct_vector_2;

/*!
A function object providing
`Point_2 operator()(const Point_2& p, const Vector_2& v)`, which returns the point `p + v`.

A model of `Kernel::ConstructTranslatedPoint_2`.
*/
typedef unspecified_type Construct_translated_point_2;

/// @}

/// \name Operations
/// The following functions give access to the predicate and construction objects.
/// @{

/// returns an `Orientation_2` object.
Orientation_2 orientation_2_object() const;

/// returns an `Exact_orientation_2` object.
Exact_orientation_2 exact_orientation_2_object() const;

/// returns a `Construct_midpoint_2` object.
Construct_midpoint_2 construct_midpoint_2_object() const;

/// returns a `Construct_barycenter_2` object.
Construct_barycenter_2 construct_barycenter_2_object() const;

/// returns a `Compute_area_2` object.
Compute_area_2 compute_area_2_object() const;

/// returns a `Construct_vector_2` object.
Construct_vector_2 construct_vector_2_object() const;

/// returns a `Construct_translated_point_2` object.
Construct_translated_point_2 construct_translated_point_2_object() const;

/// @}

}; /* end ProgressiveEmbeddingTraits_2 */
