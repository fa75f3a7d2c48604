//! Ray intersections with the analytic surfaces a library mesh tessellates (sphere, plane,
//! cube), for [`super::Geometry::Exact`].

use glam::{DVec2, DVec3};

/// A hit: the point, the normal, the texture coordinates and whether the face is a front face.
pub(super) type Hit = (DVec3, DVec3, DVec2, bool);

fn facing(d: DVec3, n: DVec3, mirror: bool) -> bool {
    (d.dot(n) < 0.0) != mirror
}

pub(super) fn hit_sphere(o: DVec3, d: DVec3, r: f64, cull: bool, mirror: bool) -> Option<Hit> {
    // |o + t d|^2 = r^2, t in [0, 1].
    let a = d.dot(d);
    let b = o.dot(d);
    let c = o.dot(o) - r * r;
    let disc = b * b - a * c;
    if disc < 0.0 {
        return None;
    }
    let sq = disc.sqrt();
    // Numerically stable roots.
    let q = -(b + sq.copysign(b));
    let mut ts = [q / a, if q != 0.0 { c / q } else { q / a }];
    ts.sort_by(|x, y| x.total_cmp(y));
    for t in ts {
        if !(0.0..=1.0).contains(&t) {
            continue;
        }
        let p = o + d * t;
        let n = p / r;
        let front = facing(d, n, mirror);
        if cull && !front {
            continue;
        }
        let theta = (n.y.clamp(-1.0, 1.0)).acos();
        let phi = n.x.atan2(n.z).rem_euclid(std::f64::consts::TAU);
        let uv = DVec2::new(phi / std::f64::consts::TAU, theta / std::f64::consts::PI);
        return Some((p, n, uv, front));
    }
    None
}

pub(super) fn hit_plane(o: DVec3, d: DVec3, size: f64, cull: bool, mirror: bool) -> Option<Hit> {
    if d.y == 0.0 {
        return None;
    }
    let t = -o.y / d.y;
    if !(0.0..=1.0).contains(&t) {
        return None;
    }
    let p = o + d * t;
    let half = size / 2.0;
    if p.x.abs() > half || p.z.abs() > half {
        return None;
    }
    let n = DVec3::Y;
    let front = facing(d, n, mirror);
    if cull && !front {
        return None;
    }
    let uv = DVec2::new((p.x + half) / size, (p.z + half) / size);
    Some((DVec3::new(p.x, 0.0, p.z), n, uv, front))
}

pub(super) fn hit_cube(o: DVec3, d: DVec3, size: f64, cull: bool, mirror: bool) -> Option<Hit> {
    let h = size / 2.0;
    let mut best: Option<(f64, Hit)> = None;
    for axis in 0..3 {
        for sign in [1.0, -1.0] {
            if d[axis] == 0.0 {
                continue;
            }
            let t = (sign * h - o[axis]) / d[axis];
            if !(0.0..=1.0).contains(&t) {
                continue;
            }
            let p = o + d * t;
            let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
            if p[a].abs() > h || p[b].abs() > h {
                continue;
            }
            let mut n = DVec3::ZERO;
            n[axis] = sign;
            let front = facing(d, n, mirror);
            if cull && !front {
                continue;
            }
            if best.as_ref().is_none_or(|(bt, _)| t < *bt) {
                best = Some((t, (p, n, DVec2::ZERO, front)));
            }
        }
    }
    best.map(|(_, hit)| hit)
}
