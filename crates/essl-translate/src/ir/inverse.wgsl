// GLSL's inverse(), which WGSL, MSL and HLSL lack: the adjugate (the transposed matrix of
// cofactors) divided by the determinant.

fn inverse2x2(m: mat2x2f) -> mat2x2f {
    return mat2x2f(m[1][1], -m[0][1], -m[1][0], m[0][0]) * (1.0 / determinant(m));
}

fn inverse3x3(m: mat3x3f) -> mat3x3f {
    let cofactors = mat3x3f(cross(m[1], m[2]), cross(m[2], m[0]), cross(m[0], m[1]));
    return transpose(cofactors) * (1.0 / dot(m[0], cofactors[0]));
}

fn inverse4x4(m: mat4x4f) -> mat4x4f {
    // The cofactors from the cross products of the columns' first three rows (E. Lengyel,
    // Foundations of Game Engine Development 1, 1.7.5).
    let a = m[0].xyz;
    let b = m[1].xyz;
    let c = m[2].xyz;
    let d = m[3].xyz;
    let x = m[0].w;
    let y = m[1].w;
    let z = m[2].w;
    let w = m[3].w;
    let inv_det = 1.0 / (dot(cross(a, b), c * w - d * z) + dot(cross(c, d), a * y - b * x));
    let s = cross(a, b) * inv_det;
    let t = cross(c, d) * inv_det;
    let u = (a * y - b * x) * inv_det;
    let v = (c * w - d * z) * inv_det;
    return transpose(mat4x4f(
        vec4f(cross(b, v) + t * y, -dot(b, t)),
        vec4f(cross(v, a) - t * x, dot(a, t)),
        vec4f(cross(d, u) + s * w, -dot(d, s)),
        vec4f(cross(u, c) - s * z, dot(c, s)),
    ));
}
