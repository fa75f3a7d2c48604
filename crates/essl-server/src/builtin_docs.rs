//! One line about each built-in function and variable of GLSL ES 3.00 and 1.00 (after the
//! specification's chapter 8 and section 7), shown on hover and in completion.

/// `(name, what it does)`, by the specification's sections.
pub const FUNCTIONS: &[(&str, &str)] = &[
    // 8.1 angle and trigonometry
    ("radians", "Degrees to radians: `π / 180 · degrees`."),
    ("degrees", "Radians to degrees: `180 / π · radians`."),
    ("sin", "The sine of an angle in radians."),
    ("cos", "The cosine of an angle in radians."),
    ("tan", "The tangent of an angle in radians."),
    ("asin", "The arc sine, in [-π/2, π/2]; undefined when |x| > 1."),
    ("acos", "The arc cosine, in [0, π]; undefined when |x| > 1."),
    ("atan", "The arc tangent: `atan(y, x)` in [-π, π] (undefined at x = y = 0), `atan(y_over_x)` in [-π/2, π/2]."),
    ("sinh", "The hyperbolic sine."),
    ("cosh", "The hyperbolic cosine."),
    ("tanh", "The hyperbolic tangent."),
    ("asinh", "The inverse hyperbolic sine."),
    ("acosh", "The inverse hyperbolic cosine; undefined when x < 1."),
    ("atanh", "The inverse hyperbolic tangent; undefined when |x| ≥ 1."),
    // 8.2 exponential
    ("pow", "x raised to the y; undefined when x < 0, or x = 0 and y ≤ 0."),
    ("exp", "The natural exponential, eˣ."),
    ("log", "The natural logarithm; undefined when x ≤ 0."),
    ("exp2", "2 raised to the x."),
    ("log2", "The base-2 logarithm; undefined when x ≤ 0."),
    ("sqrt", "The square root; undefined when x < 0."),
    ("inversesqrt", "1 / √x; undefined when x ≤ 0."),
    // 8.3 common
    ("abs", "The absolute value."),
    ("sign", "1.0 when x > 0, 0.0 when x = 0, -1.0 when x < 0."),
    ("floor", "The nearest integer less than or equal to x."),
    ("trunc", "The nearest integer whose absolute value is not larger than x's."),
    ("round", "The nearest integer (halves round in an implementation-chosen direction)."),
    ("roundEven", "The nearest integer, halves to the even one."),
    ("ceil", "The nearest integer greater than or equal to x."),
    ("fract", "x − floor(x)."),
    ("mod", "x − y · floor(x / y)."),
    ("modf", "The fractional part of x; the whole part goes to the `out` argument."),
    ("min", "The smaller of x and y."),
    ("max", "The larger of x and y."),
    ("clamp", "min(max(x, minVal), maxVal); undefined when minVal > maxVal."),
    ("mix", "x · (1 − a) + y · a; with a bool `a`, picks y where a is true."),
    ("step", "0.0 when x < edge, else 1.0."),
    ("smoothstep", "Hermite interpolation from 0 to 1 between edge0 and edge1; undefined when edge0 ≥ edge1."),
    ("isnan", "Whether x is a NaN (may always be false where NaNs are not supported)."),
    ("isinf", "Whether x is an infinity."),
    ("floatBitsToInt", "The bits of a float as an int."),
    ("floatBitsToUint", "The bits of a float as a uint."),
    ("intBitsToFloat", "An int's bits as a float."),
    ("uintBitsToFloat", "A uint's bits as a float."),
    // 8.4 packing
    ("packSnorm2x16", "Two floats in [-1, 1] packed as 16-bit signed normalized values into a uint."),
    ("unpackSnorm2x16", "A uint unpacked into two 16-bit signed normalized floats."),
    ("packUnorm2x16", "Two floats in [0, 1] packed as 16-bit unsigned normalized values into a uint."),
    ("unpackUnorm2x16", "A uint unpacked into two 16-bit unsigned normalized floats."),
    ("packHalf2x16", "Two floats packed as half floats into a uint."),
    ("unpackHalf2x16", "A uint unpacked into two half floats."),
    // 8.5 geometric
    ("length", "The length of a vector."),
    ("distance", "The distance between two points: length(p0 − p1)."),
    ("dot", "The dot product."),
    ("cross", "The cross product of two vec3."),
    ("normalize", "The vector of length 1 in x's direction; undefined for a zero vector."),
    ("faceforward", "N if dot(Nref, I) < 0, else −N."),
    ("reflect", "The reflection of I about the normal N (N should be normalized)."),
    ("refract", "The refraction of I through the surface of normal N with ratio eta."),
    // 8.6 matrices
    ("matrixCompMult", "The component-wise product of two matrices."),
    ("outerProduct", "The matrix c · rᵀ of two vectors."),
    ("transpose", "The transpose of a matrix."),
    ("determinant", "The determinant of a square matrix."),
    ("inverse", "The inverse of a square matrix; undefined when it is singular."),
    // 8.7 vector relational
    ("lessThan", "Component-wise x < y."),
    ("lessThanEqual", "Component-wise x ≤ y."),
    ("greaterThan", "Component-wise x > y."),
    ("greaterThanEqual", "Component-wise x ≥ y."),
    ("equal", "Component-wise x == y."),
    ("notEqual", "Component-wise x != y."),
    ("any", "Whether any component is true."),
    ("all", "Whether every component is true."),
    ("not", "The component-wise logical complement."),
    // 8.8 texture lookup
    ("textureSize", "The size of a level of detail of a sampler's texture."),
    ("texture", "A texel lookup at a coordinate (with an optional bias in fragment shaders)."),
    ("textureProj", "A texture lookup with projection: the coordinate divided by its last component."),
    ("textureLod", "A texture lookup at an explicit level of detail."),
    ("textureOffset", "A texture lookup with a constant texel offset."),
    ("texelFetch", "One texel by integer coordinate and level, no filtering."),
    ("texelFetchOffset", "texelFetch with a constant texel offset."),
    ("textureProjOffset", "A projective texture lookup with a constant offset."),
    ("textureLodOffset", "A lookup at an explicit level of detail with a constant offset."),
    ("textureProjLod", "A projective lookup at an explicit level of detail."),
    ("textureProjLodOffset", "A projective lookup at an explicit level of detail with an offset."),
    ("textureGrad", "A texture lookup with explicit gradients."),
    ("textureGradOffset", "A lookup with explicit gradients and a constant offset."),
    ("textureProjGrad", "A projective lookup with explicit gradients."),
    ("textureProjGradOffset", "A projective lookup with explicit gradients and an offset."),
    ("texture2D", "GLSL ES 1.00: a 2D texture lookup."),
    ("texture2DProj", "GLSL ES 1.00: a projective 2D texture lookup."),
    ("texture2DLod", "GLSL ES 1.00 (vertex shaders): a 2D lookup at an explicit level."),
    ("texture2DProjLod", "GLSL ES 1.00 (vertex shaders): a projective 2D lookup at an explicit level."),
    ("textureCube", "GLSL ES 1.00: a cube map lookup."),
    ("textureCubeLod", "GLSL ES 1.00 (vertex shaders): a cube map lookup at an explicit level."),
    // 8.9 fragment processing
    ("dFdx", "The derivative of p in x (fragment shaders)."),
    ("dFdy", "The derivative of p in y (fragment shaders)."),
    ("fwidth", "abs(dFdx(p)) + abs(dFdy(p)) (fragment shaders)."),
];

/// `(name, what it is)` for the built-in variables.
pub const VARIABLES: &[(&str, &str)] = &[
    (
        "gl_Position",
        "The vertex's clip-space position, written by the vertex shader.",
    ),
    (
        "gl_PointSize",
        "The size of a point being drawn, in pixels.",
    ),
    ("gl_VertexID", "The index of the vertex being processed."),
    ("gl_InstanceID", "The index of the instance being drawn."),
    (
        "gl_FragCoord",
        "The fragment's window position: x, y in pixels, z the depth, w = 1 / clip w.",
    ),
    (
        "gl_FrontFacing",
        "Whether the fragment belongs to a front-facing primitive.",
    ),
    (
        "gl_PointCoord",
        "The fragment's position inside a point, from 0 to 1.",
    ),
    (
        "gl_FragDepth",
        "The fragment's depth, when the shader writes it.",
    ),
    ("gl_FragColor", "GLSL ES 1.00: the fragment's colour."),
    (
        "gl_FragData",
        "GLSL ES 1.00: the fragment's colours, one per draw buffer.",
    ),
    (
        "gl_ClipDistance",
        "GL_ANGLE_clip_cull_distance: the vertex's distances to the user clip planes; the \
         primitive is clipped where an enabled one is negative. Fragment shaders read them \
         interpolated.",
    ),
    (
        "gl_CullDistance",
        "GL_ANGLE_clip_cull_distance: distances that cull a primitive whose vertices are all \
         negative; essl offers none (gl_MaxCullDistances is 0).",
    ),
];

/// The line about a built-in function or variable.
pub fn doc(name: &str) -> Option<&'static str> {
    FUNCTIONS
        .iter()
        .chain(VARIABLES)
        .find(|(n, _)| *n == name)
        .map(|(_, d)| *d)
}
