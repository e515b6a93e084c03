//! Closed-form sweeps of a ball against the world's simple shapes: a half-space, a box, a
//! triangle and a convex hull (a ramp).
//!
//! Written here rather than taken from parry3d because a locomotion graph sweeps small balls
//! dozens of times per character and frame (each foot's landing grid alone traces 9 + 1),
//! and parry3d answers ball-versus-convex casts through its general support-map algorithm
//! (GJK): on the stairs scenario that was 90 % of a frame, about 20 times the cost of the
//! forms below. Each one is checked against parry3d's cast on random sweeps in the world
//! tests; the world falls back to parry3d whenever the ball starts overlapping a shape.
//!
//! A ball of radius `r` whose centre moves along a ray first touches a shape where the ray
//! enters the shape grown by `r` (its Minkowski sum with the ball). For a box that is the
//! union of the box grown along each axis alone, a cylinder of radius `r` around each edge
//! and a ball around each corner; for a triangle, the triangle thickened by `r` on both
//! sides, the cylinders around its edges and the balls around its corners. The first entry
//! into the union is the smallest entry into any of its parts. All distances in
//! centimetres; `dir` is a unit vector and `length` the sweep's length along it.

use glam::Vec3;
use parry3d::bounding_volume::Aabb;

/// What a ball's sweep against one shape found.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum BallSweep {
    /// The ball does not touch the shape within the sweep.
    Miss,
    /// First contact after the centre travelled `distance`; `normal` is the shape's unit
    /// surface normal there, pointing at the ball.
    Hit { distance: f32, normal: Vec3 },
    /// The ball already overlaps the shape at the start (the caller decides what that means).
    Overlap,
}

/// A triangle and its unit normal `(b − a) × (c − a)`, normalised once when its shape is
/// built instead of at every sweep (`None` for a degenerate triangle).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Facet {
    /// The corners `a`, `b`, `c`.
    pub(crate) corners: [Vec3; 3],
    /// The unit normal of [`Facet::normal_of`].
    pub(crate) normal: Option<Vec3>,
}

impl Facet {
    /// The facet of the triangle `corners`.
    pub(crate) fn new(corners: [Vec3; 3]) -> Self {
        Self {
            corners,
            normal: Self::normal_of(corners),
        }
    }

    /// The unit normal `(b − a) × (c − a)` of the triangle `[a, b, c]`; `None` for a
    /// degenerate one.
    pub(crate) fn normal_of([a, b, c]: [Vec3; 3]) -> Option<Vec3> {
        (b - a).cross(c - a).try_normalize()
    }
}

/// Where a sphere of `radius` whose centre moves from `start` along the unit vector `dir`
/// for up to `length` first touches the half-space below the plane through `point` with
/// unit `normal`: the distance travelled, 0 when it starts touching or inside (if
/// `stop_at_penetration`; else a sphere starting inside does not hit).
/// `World::plane_sphere_traces` computes the same for a flat world's batch of sphere
/// traces, operation for operation: a change here must be made there too.
pub(crate) fn ball_half_space_sweep(
    start: Vec3,
    dir: Vec3,
    length: f32,
    radius: f32,
    point: Vec3,
    normal: Vec3,
    stop_at_penetration: bool,
) -> Option<f32> {
    // Signed distance from the sphere's lowest point (towards the plane) to the plane.
    let gap = normal.dot(start - point) - radius;
    if gap <= 0.0 {
        return stop_at_penetration.then_some(0.0);
    }
    let approach = -normal.dot(dir);
    if approach <= 0.0 {
        return None;
    }
    let distance = gap / approach;
    (distance <= length).then_some(distance)
}

/// A ball of `radius` swept from `start` along `dir` for `length`, against the box
/// `[−half, half]` (all in the box's own frame).
pub(crate) fn ball_box_sweep(
    start: Vec3,
    dir: Vec3,
    length: f32,
    radius: f32,
    half: Vec3,
) -> BallSweep {
    let outside = start - start.clamp(-half, half);
    if outside.length_squared() <= radius * radius {
        return BallSweep::Overlap;
    }
    // The box grown by `radius` on every side holds the whole rounded box: a ray that misses
    // it misses the ball's sweep, and one entering it through the middle of a face (outside
    // the grown box's edge and corner regions) touches that face first.
    let grown = half + radius;
    let Some(t) = ray_box_entry(start, dir, length, grown) else {
        return BallSweep::Miss;
    };
    let at = start + dir * t;
    let beyond = at.abs().cmpgt(half);
    if t > 0.0 && beyond.bitmask().count_ones() == 1 {
        return BallSweep::Hit {
            distance: t,
            normal: box_normal(at, half),
        };
    }
    // The entry point lies beside an edge (two axes beyond the box) or a corner (three):
    // there the grown box is wider than the rounded one, and the ball can only touch that
    // edge's or that corner's three edges' capsules first. A ray through an edge region
    // that misses the edge's capsule misses the rounded box: to reach a face region it
    // would cross the capsule (the method of Ericson, "Real-Time Collision Detection",
    // 5.5.7). Fewer than two axes beyond with `t = 0` is a start within rounding of the
    // surface: left to parry3d, as an overlap.
    let corner = at.signum() * half;
    let mut best = f32::INFINITY;
    let mut enter = |t: Option<f32>| {
        if let Some(t) = t {
            best = best.min(t);
        }
    };
    match beyond.bitmask() {
        0b111 => {
            // The corner's ball, and each edge from it with the ball at its far end.
            enter(ray_sphere_entry(start, dir, length, corner, radius));
            for axis in 0..3 {
                let mut other = corner;
                other[axis] = -other[axis];
                enter(ray_cylinder_entry(
                    start, dir, length, corner, other, radius,
                ));
                enter(ray_sphere_entry(start, dir, length, other, radius));
            }
        }
        m if m.count_ones() == 2 => {
            // The edge along the one axis not beyond, with the balls at its ends.
            let axis = (!m & 0b111).trailing_zeros() as usize;
            let (mut a, mut b) = (corner, corner);
            a[axis] = -half[axis];
            b[axis] = half[axis];
            enter(ray_cylinder_entry(start, dir, length, a, b, radius));
            enter(ray_sphere_entry(start, dir, length, a, radius));
            enter(ray_sphere_entry(start, dir, length, b, radius));
        }
        _ => return BallSweep::Overlap,
    }
    if best > length {
        return BallSweep::Miss;
    }
    BallSweep::Hit {
        distance: best,
        normal: box_normal(start + dir * best, half),
    }
}

/// The unit normal of the box `[−half, half]` facing the point `at` outside it: from the
/// nearest point of the box towards `at` (a face, edge or corner normal alike).
fn box_normal(at: Vec3, half: Vec3) -> Vec3 {
    (at - at.clamp(-half, half))
        .try_normalize()
        .unwrap_or(Vec3::Z)
}

/// What the face of a triangle (its plane thickened by the ball's radius, within the
/// triangle) says about a ball's sweep against the triangle.
enum Face {
    /// The ball overlaps the triangle at the start.
    Overlap,
    /// The ball touches the face first, after `distance`: no edge or corner of this
    /// triangle comes sooner.
    Hit { distance: f32, normal: Vec3 },
    /// The face is not touched first, or not within the sweep, or the triangle is
    /// degenerate: only the triangle's edges and corners can be.
    Edges,
}

/// A ball of `radius` swept from `start` along `dir` for `length`, against the face of the
/// two-sided triangle `facet`.
fn ball_face_sweep(start: Vec3, dir: Vec3, length: f32, radius: f32, facet: &Facet) -> Face {
    let corners = facet.corners;
    let a = corners[0];
    let Some(normal) = facet.normal else {
        // A degenerate triangle is its edges.
        return Face::Edges;
    };
    let height = normal.dot(start - a);
    if height.abs() <= radius {
        if inside_triangle(start - normal * height, corners, normal) {
            return Face::Overlap;
        }
        // Touching the plane but beside the triangle: only an edge or a corner can be
        // touched (or overlapped) first.
        return Face::Edges;
    }
    // The face: the triangle's plane moved `radius` towards the start, crossed inside the
    // triangle. Every point within `radius` of an edge or corner is within `radius` of the
    // plane, which the ball reaches no sooner than this; so a face hit is the first.
    let side = if height > 0.0 { 1.0 } else { -1.0 };
    let approach = -side * normal.dot(dir);
    if approach > 0.0 {
        let t = (height.abs() - radius) / approach;
        let centre = start + dir * t;
        if t <= length && inside_triangle(centre - normal * (side * radius), corners, normal) {
            return Face::Hit {
                distance: t,
                normal: normal * side,
            };
        }
    }
    Face::Edges
}

/// A convex hull's triangle ([`hull_facets`]): the triangle and its unit outward normal
/// (`None` for a degenerate triangle, or for every triangle of a hull without volume).
pub(crate) type HullTriangle = (Facet, Option<Vec3>);

/// A face's plane: its unit outward normal and offset (inside is `normal · p ≤ offset`).
pub(crate) type Plane = (Vec3, f32);

/// A convex hull's surface for [`ball_hull_sweep`], from its `vertices` and triangles
/// (`indices` into them): each triangle with its unit normal turned to face away from the
/// vertices' centre (`None` for a degenerate triangle), and each face's plane (that normal
/// and its offset: inside is `normal · p ≤ offset`). A hull without volume (a plate, whose
/// centre lies in its own plane, so that "away from the centre" means nothing) gets no
/// outward normals: every triangle is swept against.
pub(crate) fn hull_facets(
    vertices: &[Vec3],
    indices: &[[u32; 3]],
) -> (Vec<HullTriangle>, Vec<Plane>) {
    let centre = vertices.iter().copied().sum::<Vec3>() / vertices.len().max(1) as f32;
    let extent = vertices
        .iter()
        .map(|&v| (v - centre).length())
        .fold(0.0_f32, f32::max);
    let mut triangles: Vec<HullTriangle> = indices
        .iter()
        .map(|t| {
            let facet = Facet::new(t.map(|i| vertices[i as usize]));
            let a = facet.corners[0];
            let outward = facet
                .normal
                .map(|n| if n.dot(a - centre) < 0.0 { -n } else { n });
            (facet, outward)
        })
        .collect();
    let planes = triangles
        .iter()
        .filter_map(|&(facet, outward)| outward.map(|n| (n, n.dot(facet.corners[0]))))
        .collect();
    // The centre of a hull with volume lies well inside every face's plane (a third of a
    // thin ramp's height); within 1e-4 of the hull's size, the hull is flat.
    let flat = triangles.iter().any(|&(facet, outward)| {
        outward.is_some_and(|n| n.dot(facet.corners[0] - centre) <= 1e-4 * extent)
    });
    if flat {
        for (_, outward) in &mut triangles {
            *outward = None;
        }
    }
    (triangles, planes)
}

/// A ball of `radius` swept from `start` along `dir` for `length`, against the solid convex
/// hull bounded by `triangles` (its surface, each with its unit outward normal, `None` for
/// a degenerate one: [`hull_facets`]) and `planes` (each face's unit outward normal and
/// offset: inside is `normal · p ≤ offset` for every face).
///
/// From outside, the ball meets the hull's surface first; the triangles' edges inside a
/// face (its diagonals) lie within the grown hull, so they never come first. Nor does a
/// triangle facing away from the sweep (`outward · dir ≥ 0`) whose plane lies farther
/// than `radius` from the start ([`hull_facing`] leaves them out): from the outer side of
/// its plane the ball never comes within `radius` of it; from the inner side it can touch
/// the face only after overlapping the hull; and a first contact on one of its edges or
/// corners lies on a face that faces the sweep or, grazing it, on a face within `radius`
/// of the start, whose triangles are kept. So is every triangle the ball may overlap at
/// the start.
pub(crate) fn ball_hull_sweep(
    start: Vec3,
    dir: Vec3,
    length: f32,
    radius: f32,
    triangles: &[HullTriangle],
    planes: &[Plane],
) -> BallSweep {
    if planes.iter().all(|&(n, d)| n.dot(start) <= d) {
        return BallSweep::Overlap;
    }
    let facing = hull_facing(triangles, start, dir, radius);
    ball_triangles_sweep(start, dir, length, radius, facing)
}

/// The triangles of a convex hull ([`hull_facets`]) that a ball of `radius` swept from
/// `start` along `dir` may touch first or overlap at the start: all but those whose
/// outward normal does not face the sweep and whose plane lies farther than `radius` from
/// the start ([`ball_hull_sweep`] says why).
fn hull_facing(
    triangles: &[HullTriangle],
    start: Vec3,
    dir: Vec3,
    radius: f32,
) -> impl Iterator<Item = Facet> {
    triangles.iter().filter_map(move |&(facet, outward)| {
        let away = outward
            .is_some_and(|n| n.dot(dir) >= 0.0 && n.dot(start - facet.corners[0]).abs() > radius);
        (!away).then_some(facet)
    })
}

/// A ball of `radius` swept from `start` along `dir` for `length`, against each of
/// `triangles` (two-sided): the nearest hit (of equal distances the first face, then the
/// first edge or corner; past [`EDGES_LATER`] triangles whose edges wait, a later one's
/// edges are tested in turn with the faces), or an overlap with any.
///
/// The faces first, then the edges and corners of the triangles whose face is not touched
/// first, each only up to the nearest hit so far. The edges are most of a sweep's cost
/// (a heightfield's sweep meets four triangles, and the face of one), and the nearest hit
/// rules many of them out before any is tested: there the ball touches the tangent plane
/// (through the contact, across the normal), coming from the side the normal points to,
/// so before the contact it lies wholly on that side, and an edge whose ends both lie on
/// the plane or behind it cannot be touched sooner, nor overlap the ball at the start.
/// On ground that is flat or rounded upwards around the contact, the neighbouring
/// triangles' edges all do. (The heights are compared as computed: an edge that rounding
/// puts on the plane can be touched no sooner than by the rounding of the heights.)
pub(crate) fn ball_triangles_sweep(
    start: Vec3,
    dir: Vec3,
    length: f32,
    radius: f32,
    triangles: impl IntoIterator<Item = Facet>,
) -> BallSweep {
    let mut nearest = Nearest::new(start, dir, length, radius);
    // The triangles whose edges are left for after the faces, on the stack (a sweep meets
    // a handful); past that many, a triangle's edges are tested at once.
    let mut later = [[Vec3::ZERO; 3]; EDGES_LATER];
    let mut held = 0;
    for facet in triangles {
        let corners = facet.corners;
        match ball_face_sweep(start, dir, nearest.reach, radius, &facet) {
            Face::Overlap => return BallSweep::Overlap,
            Face::Hit { distance, normal } => nearest.offer(distance, normal),
            Face::Edges if held < EDGES_LATER => {
                later[held] = corners;
                held += 1;
            }
            Face::Edges => {
                if nearest.edges(corners) {
                    return BallSweep::Overlap;
                }
            }
        }
    }
    for &corners in &later[..held] {
        if nearest.edges(corners) {
            return BallSweep::Overlap;
        }
    }
    nearest.found()
}

/// How many triangles' edges [`ball_triangles_sweep`] holds back until after the faces.
const EDGES_LATER: usize = 8;

/// The nearest hit of a ball's sweep so far ([`ball_triangles_sweep`]): how far a later
/// hit may lie (the whole sweep while there is none) and the tangent plane at the hit.
struct Nearest {
    /// The sweep's start (cm).
    start: Vec3,
    /// Its unit direction.
    dir: Vec3,
    /// The ball's radius (cm).
    radius: f32,
    /// The sweep's length up to the nearest hit (cm).
    reach: f32,
    /// The nearest hit's unit normal and the height along it of its tangent plane
    /// (`normal · contact`; −∞, ruling nothing out, for a normal that does not face the
    /// sweep, which a first contact's does), if there is a hit.
    hit: Option<(Vec3, f32)>,
}

impl Nearest {
    /// No hit yet: a ball of `radius` swept from `start` along the unit `dir` for
    /// `length`.
    fn new(start: Vec3, dir: Vec3, length: f32, radius: f32) -> Self {
        Self {
            start,
            dir,
            radius,
            reach: length,
            hit: None,
        }
    }

    /// A hit after `distance` with unit `normal`, kept if it is nearer than the nearest so
    /// far (a tie does not replace it).
    fn offer(&mut self, distance: f32, normal: Vec3) {
        if self.hit.is_some() && self.reach <= distance {
            return;
        }
        self.reach = distance;
        let contact = self.start + self.dir * distance - normal * self.radius;
        let height = if normal.dot(self.dir) < 0.0 {
            normal.dot(contact)
        } else {
            f32::NEG_INFINITY
        };
        self.hit = Some((normal, height));
    }

    /// The edges and corners of the triangle `corners`, each tested up to the nearest hit
    /// unless both its ends lie on the nearest hit's tangent plane or behind it; true when
    /// the ball overlaps one at the start.
    fn edges(&mut self, corners: [Vec3; 3]) -> bool {
        let behind = match self.hit {
            Some((normal, height)) => corners.map(|p| normal.dot(p) <= height),
            None => [false; 3],
        };
        if behind == [true; 3] {
            return false;
        }
        match ball_edges_sweep(
            self.start,
            self.dir,
            self.reach,
            self.radius,
            corners,
            behind,
        ) {
            BallSweep::Overlap => true,
            BallSweep::Hit { distance, normal } => {
                self.offer(distance, normal);
                false
            }
            BallSweep::Miss => false,
        }
    }

    /// The sweep's answer: the nearest hit, or a miss.
    fn found(&self) -> BallSweep {
        match self.hit {
            Some((normal, _)) => BallSweep::Hit {
                distance: self.reach,
                normal,
            },
            None => BallSweep::Miss,
        }
    }
}

/// The box a ball of `radius` sweeps through moving from `start` to `end`.
pub(crate) fn ball_reach(start: Vec3, end: Vec3, radius: f32) -> Aabb {
    Aabb::new(start.min(end) - radius, start.max(end) + radius)
}

/// How much (cm) the box a ball sweeps through is widened before an edge outside it is
/// skipped: far more than the rounding of the box's corners.
const EDGE_CULL_MARGIN: f32 = 0.01;

/// The sweep against a triangle's three edges and corners alone, but for the edges whose
/// ends are both `behind` (`behind[k]` for corner `k`; with such an edge, its first
/// corner).
fn ball_edges_sweep(
    start: Vec3,
    dir: Vec3,
    length: f32,
    radius: f32,
    corners: [Vec3; 3],
    behind: [bool; 3],
) -> BallSweep {
    let mut best: Option<(f32, Vec3)> = None;
    // The box the ball sweeps through, loosened against rounding: an edge whose box misses
    // it is farther than `radius` from every centre of the sweep (and so is its corner
    // `a`), so it can neither overlap the start nor be touched. Most of the edges of the
    // triangles near a short sweep miss it.
    let reach = ball_reach(start, start + dir * length, radius + EDGE_CULL_MARGIN);
    for k in 0..3 {
        let (a, b) = (corners[k], corners[(k + 1) % 3]);
        // `Aabb::intersects` without building the edge's box (measured cheaper here).
        if a.min(b).cmpgt(reach.maxs).any() || a.max(b).cmplt(reach.mins).any() {
            continue;
        }
        if behind[k] && behind[(k + 1) % 3] {
            continue;
        }
        let closest = closest_on_segment(start, a, b);
        if (start - closest).length_squared() <= radius * radius {
            return BallSweep::Overlap;
        }
        let hits = [
            ray_cylinder_entry(start, dir, length, a, b, radius),
            ray_sphere_entry(start, dir, length, a, radius),
        ];
        for t in hits.into_iter().flatten() {
            if best.is_none_or(|(d, _)| t < d) {
                let centre = start + dir * t;
                let normal = (centre - closest_on_segment(centre, a, b))
                    .try_normalize()
                    .unwrap_or(-dir);
                best = Some((t, normal));
            }
        }
    }
    match best {
        Some((distance, normal)) => BallSweep::Hit { distance, normal },
        None => BallSweep::Miss,
    }
}

/// Whether `point` (in the triangle's plane) lies inside the triangle or on its border;
/// `normal` is the triangle's unit normal `(b − a) × (c − a)`.
fn inside_triangle(point: Vec3, [a, b, c]: [Vec3; 3], normal: Vec3) -> bool {
    (b - a).cross(point - a).dot(normal) >= 0.0
        && (c - b).cross(point - b).dot(normal) >= 0.0
        && (a - c).cross(point - c).dot(normal) >= 0.0
}

/// The point of the segment `a → b` nearest to `point`.
fn closest_on_segment(point: Vec3, a: Vec3, b: Vec3) -> Vec3 {
    let ab = b - a;
    let len2 = ab.length_squared();
    if len2 <= 0.0 {
        return a;
    }
    a + ab * ((point - a).dot(ab) / len2).clamp(0.0, 1.0)
}

/// Where the ray `start + dir·t`, `0 ≤ t ≤ length`, enters the box `[−half, half]`: 0 when
/// it starts inside (slab test).
fn ray_box_entry(start: Vec3, dir: Vec3, length: f32, half: Vec3) -> Option<f32> {
    let (mut near, mut far) = (0.0_f32, length);
    for axis in 0..3 {
        let (p, d, h) = (start[axis], dir[axis], half[axis]);
        if d == 0.0 {
            if p.abs() > h {
                return None;
            }
            continue;
        }
        let (t0, t1) = ((-h - p) / d, (h - p) / d);
        let (t0, t1) = if t0 <= t1 { (t0, t1) } else { (t1, t0) };
        near = near.max(t0);
        far = far.min(t1);
        if near > far {
            return None;
        }
    }
    Some(near)
}

/// Where the ray `start + dir·t`, `0 ≤ t ≤ length`, enters the ball of `radius` around
/// `centre`; `None` for a start inside it (the callers check overlap first).
#[inline(always)]
fn ray_sphere_entry(start: Vec3, dir: Vec3, length: f32, centre: Vec3, radius: f32) -> Option<f32> {
    let m = start - centre;
    let b = m.dot(dir);
    let c = m.length_squared() - radius * radius;
    if c <= 0.0 || b >= 0.0 {
        return None;
    }
    let disc = b * b - c;
    if disc < 0.0 {
        return None;
    }
    let t = (-b - disc.sqrt()).max(0.0);
    (t <= length).then_some(t)
}

/// Where the ray `start + dir·t`, `0 ≤ t ≤ length`, enters the cylinder of `radius` around
/// the segment `a → b` (without its end caps: the balls at the ends cover them); `None` for
/// a start inside it or a ray parallel to it.
#[inline(always)]
fn ray_cylinder_entry(
    start: Vec3,
    dir: Vec3,
    length: f32,
    a: Vec3,
    b: Vec3,
    radius: f32,
) -> Option<f32> {
    let axis = b - a;
    let axis_len = axis.length();
    if axis_len <= 0.0 {
        return None;
    }
    let e = axis / axis_len;
    let m = start - a;
    // The problem across the axis: a circle of `radius` in the plane perpendicular to it.
    let m_across = m - e * m.dot(e);
    let d_across = dir - e * dir.dot(e);
    let qa = d_across.length_squared();
    let qb = m_across.dot(d_across);
    let qc = m_across.length_squared() - radius * radius;
    if qa <= 1e-12 || qc <= 0.0 || qb >= 0.0 {
        return None;
    }
    let disc = qb * qb - qa * qc;
    if disc < 0.0 {
        return None;
    }
    let t = ((-qb - disc.sqrt()) / qa).max(0.0);
    let along = (m + dir * t).dot(e);
    (t <= length && (0.0..=axis_len).contains(&along)).then_some(t)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::signed;

    #[test]
    fn an_edge_just_above_the_nearest_face_is_touched_first() {
        // A ball of radius 5 falls straight down from (0, 0, 20) onto the level triangle
        // A (z = 0), whose face it would touch after 15 cm. Triangle B's edge runs along
        // y = `y` at z = `z`, just above A's plane, and B falls away from it to z = −5, so
        // B's face is not touched first: the edge is, when the centre is 5 cm from it, at
        // z + √(25 − y²) (by hand): 0.04 cm sooner than A's face for the edge 0.05 cm
        // above it, 0.000 75 cm for the one 0.001 cm above. Both orders of the triangles.
        // Ruling out edges that lie that little in front of A's plane gives A's face.
        let a = [
            Vec3::new(-20.0, -20.0, 0.0),
            Vec3::new(20.0, -20.0, 0.0),
            Vec3::new(0.0, 20.0, 0.0),
        ];
        for (y, z) in [(0.3_f32, 0.05_f32), (0.05, 0.001)] {
            let b = [
                Vec3::new(-10.0, y, z),
                Vec3::new(10.0, y, z),
                Vec3::new(0.0, 10.0, -5.0),
            ];
            let (y64, z64) = (f64::from(y), f64::from(z));
            let expected = 20.0 - (z64 + (25.0 - y64 * y64).sqrt());
            for triangles in [[a, b], [b, a]] {
                let start = Vec3::new(0.0, 0.0, 20.0);
                let facets = triangles.map(Facet::new);
                match ball_triangles_sweep(start, Vec3::NEG_Z, 40.0, 5.0, facets) {
                    BallSweep::Hit { distance, normal } => {
                        let error = (f64::from(distance) - expected).abs();
                        assert!(error < 1e-5, "{distance} vs {expected}");
                        // From the edge to the centre: up, leaning away from the edge.
                        let want = Vec3::new(0.0, -y, (25.0 - y * y).sqrt()).normalize();
                        assert!((normal - want).length() < 1e-3, "{normal} vs {want}");
                    }
                    other => panic!("{other:?}"),
                }
            }
        }
    }

    /// Checks that two answers to one sweep agree up to rounding: the same overlap or
    /// miss, or hits at distances `relative` of the distance apart, with the same normal
    /// (to 1e-3) where the distances are equal (where they differ, two contacts a rounding
    /// apart may both be first); true for a hit.
    fn same_answer(ours: BallSweep, reference: BallSweep, relative: f32, context: &str) -> bool {
        let context = format!("{context}: {ours:?} vs {reference:?}");
        match (ours, reference) {
            (
                BallSweep::Hit { distance, normal },
                BallSweep::Hit {
                    distance: d,
                    normal: n,
                },
            ) => {
                assert!((distance - d).abs() <= relative * d.max(1.0), "{context}");
                if distance == d {
                    assert!((normal - n).length() < 1e-3, "{context}");
                }
                true
            }
            _ => {
                assert_eq!(ours, reference, "{context}");
                false
            }
        }
    }

    /// [`ball_triangles_sweep`] without its order or its rule: every triangle in turn, its
    /// face and then every edge and corner, up to the nearest hit so far.
    fn every_edge(
        start: Vec3,
        dir: Vec3,
        length: f32,
        radius: f32,
        triangles: &[[Vec3; 3]],
    ) -> BallSweep {
        let mut nearest = BallSweep::Miss;
        let mut reach = length;
        for &corners in triangles {
            let found = match ball_face_sweep(start, dir, reach, radius, &Facet::new(corners)) {
                Face::Overlap => BallSweep::Overlap,
                Face::Hit { distance, normal } => BallSweep::Hit { distance, normal },
                Face::Edges => ball_edges_sweep(start, dir, reach, radius, corners, [false; 3]),
            };
            match found {
                BallSweep::Overlap => return BallSweep::Overlap,
                BallSweep::Hit { distance, normal }
                    if distance < reach || matches!(nearest, BallSweep::Miss) =>
                {
                    nearest = BallSweep::Hit { distance, normal };
                    reach = distance;
                }
                _ => {}
            }
        }
        nearest
    }

    #[test]
    fn a_hull_leaves_out_only_triangles_that_cannot_come_first() {
        // A ramp (a wedge: a 40 × 30 cm base rising to 12 cm along x) and a box, each as
        // its surface triangles with outward normals and its faces' planes, swept by balls
        // from every side and direction (a few starting inside). Each answer is held against
        // the sweep over every triangle: the same overlaps and misses, the same distance
        // and normal up to rounding (1e-5 of the distance, or of 1 cm below it: where two
        // triangles of a face, or a face and its edge, are touched at once, either may
        // answer). Then which triangles a sweep keeps, on the box and on a flat plate.
        let wedge = [
            Vec3::new(0.0, 0.0, 0.0),
            Vec3::new(40.0, 0.0, 0.0),
            Vec3::new(40.0, 30.0, 0.0),
            Vec3::new(0.0, 30.0, 0.0),
            Vec3::new(40.0, 0.0, 12.0),
            Vec3::new(40.0, 30.0, 12.0),
        ];
        let wedge_faces: &[[u32; 3]] = &[
            [0, 2, 1],
            [0, 3, 2],
            [1, 2, 5],
            [1, 5, 4],
            [0, 1, 4],
            [3, 5, 2],
            [0, 4, 5],
            [0, 5, 3],
        ];
        let cube: Vec<Vec3> = (0..8)
            .map(|k| Vec3::new((k & 1) as f32, ((k >> 1) & 1) as f32, ((k >> 2) & 1) as f32) * 20.0)
            .collect();
        let cube_faces: &[[u32; 3]] = &[
            [0, 2, 1],
            [1, 2, 3],
            [4, 5, 6],
            [5, 7, 6],
            [0, 1, 4],
            [1, 5, 4],
            [2, 6, 3],
            [3, 6, 7],
            [0, 4, 2],
            [2, 4, 6],
            [1, 3, 5],
            [3, 7, 5],
        ];
        let mut r = signed(0xface);
        let mut hits = 0;
        for (corners, faces) in [(&wedge[..], wedge_faces), (&cube[..], cube_faces)] {
            let centre = corners.iter().copied().sum::<Vec3>() / corners.len() as f32;
            let (triangles, planes) = hull_facets(corners, faces);
            assert!(triangles.iter().all(|(_, outward)| outward.is_some()));
            for _ in 0..3000 {
                // Towards a point near the centre, mostly; a few anywhere.
                let start = centre + Vec3::new(r(), r(), r()) * 45.0;
                let aim = centre + Vec3::new(r(), r(), r()) * 25.0;
                let towards = if r() > -0.8 {
                    aim - start
                } else {
                    Vec3::new(r(), r(), r())
                };
                let dir = towards.normalize();
                let (length, radius) = (10.0 + r().abs() * 60.0, 0.5 + r().abs() * 6.0);
                let ours = ball_hull_sweep(start, dir, length, radius, &triangles, &planes);
                let every = if planes.iter().all(|&(n, d)| n.dot(start) <= d) {
                    BallSweep::Overlap
                } else {
                    let all = triangles.iter().map(|&(f, _)| f);
                    ball_triangles_sweep(start, dir, length, radius, all)
                };
                let context = format!("{start} {dir} {length} {radius}");
                hits += usize::from(same_answer(ours, every, 1e-5, &context));
            }
        }
        assert!(hits > 1000 && hits < 5500, "{hits} hits of 6000");
        // Straight down onto the box from 20 cm above it: only its top's two triangles are
        // swept against (its sides are 10 cm away, along the sweep; its bottom faces away).
        let (triangles, _) = hull_facets(&cube, cube_faces);
        let start = Vec3::new(10.0, 10.0, 40.0);
        let kept: Vec<Facet> = hull_facing(&triangles, start, Vec3::NEG_Z, 2.0).collect();
        assert_eq!(kept.len(), 2, "{kept:?}");
        assert!(
            kept.iter().all(|f| f.corners.iter().all(|c| c.z == 20.0)),
            "{kept:?}"
        );
        // A hull without volume (a plate, both sides): no side is away from its centre, so
        // every triangle is kept.
        let plate = [
            Vec3::ZERO,
            Vec3::X * 30.0,
            Vec3::new(30.0, 20.0, 0.0),
            Vec3::Y * 20.0,
        ];
        let sides: &[[u32; 3]] = &[[0, 1, 2], [0, 2, 3], [0, 2, 1], [0, 3, 2]];
        let (triangles, _) = hull_facets(&plate, sides);
        assert!(triangles.iter().all(|(_, outward)| outward.is_none()));
        let start = Vec3::new(10.0, 10.0, 5.0);
        assert_eq!(hull_facing(&triangles, start, Vec3::NEG_Z, 1.0).count(), 4);
    }

    #[test]
    fn edges_ruled_out_by_the_nearest_hit_change_no_answer() {
        // Patches of a rolling heightfield (rounded upwards and downwards: hills, valleys
        // and saddles), 2 to 40 triangles each (past the 8 whose edges wait for the
        // faces), swept by balls from every direction. Each answer is held against every
        // edge tested in turn: the same overlaps and misses, the same distances up to the
        // rounding of the heights, and the same normals where no other contact comes
        // within that rounding.
        let mut r = signed(0x5eed);
        let ground = |x: f32, y: f32| {
            6.0 * (x / 14.0).sin() * (y / 11.0).cos() + 2.0 * (0.3 * x + 0.2 * y).sin()
        };
        let mut hits = 0;
        for _ in 0..3000 {
            let (x0, y0) = (r() * 60.0, r() * 60.0);
            let (cols, rows) = (
                1 + (r().abs() * 4.0) as usize,
                1 + (r().abs() * 5.0) as usize,
            );
            let cell = 4.0 + r().abs() * 10.0;
            let at = |i: usize, j: usize| {
                let (x, y) = (x0 + i as f32 * cell, y0 + j as f32 * cell);
                Vec3::new(x, y, ground(x, y))
            };
            let mut triangles = Vec::new();
            for j in 0..rows {
                for i in 0..cols {
                    triangles.push([at(i, j), at(i + 1, j), at(i + 1, j + 1)]);
                    triangles.push([at(i, j), at(i + 1, j + 1), at(i, j + 1)]);
                }
            }
            let centre = at(0, 0) + Vec3::new(cols as f32, rows as f32, 0.0) * cell * 0.5;
            let start = centre + Vec3::new(r() * 20.0, r() * 20.0, 4.0 + r().abs() * 30.0);
            let dir = (Vec3::new(r(), r(), -1.5 + r())).normalize();
            let (length, radius) = (5.0 + r().abs() * 60.0, 0.5 + r().abs() * 8.0);
            let facets = triangles.iter().map(|&corners| Facet::new(corners));
            let ours = ball_triangles_sweep(start, dir, length, radius, facets);
            let reference = every_edge(start, dir, length, radius, &triangles);
            let context = format!("{start} {dir} {length} {radius}");
            hits += usize::from(same_answer(ours, reference, 1e-4, &context));
        }
        assert!(hits > 800 && hits < 2900, "{hits} hits of 3000");
    }

    /// The first contact of a ball of radius 5 against the box `[−1, 1]³` on a ray that
    /// enters the grown box beside the corner (1, 1, 1), runs along the edge towards x = −1
    /// more than a radius away from it, and closes in on the far corner (−1, 1, 1): its ball
    /// is touched first, beyond the edge's end. Expected by hand (in f64): the ray's point
    /// at distance `t` from the far corner is `r` away.
    #[test]
    fn the_far_corner_of_an_edge_can_be_touched_first() {
        let (half, radius) = (Vec3::ONE, 5.0_f32);
        // Across the edge, the ray's distance from the edge line (y = z = 1) is 5.1 at
        // x = −1 and grows by 0.9 per centimetre of x back towards +x, along the diagonal.
        let across = |x: f64| (5.1 + 0.9 * (x + 1.0)) / 2f64.sqrt();
        let point = |x: f64| [x, 1.0 + across(x), 1.0 + across(x)];
        let (p0, p1) = (point(3.0), point(-3.0));
        let d: Vec<f64> = (0..3).map(|k| p1[k] - p0[k]).collect();
        let len = d.iter().map(|v| v * v).sum::<f64>().sqrt();
        let dir: Vec<f64> = d.iter().map(|v| v / len).collect();
        // |p0 + dir·t − c|² = r² for the far corner c.
        let c = [-1.0, 1.0, 1.0];
        let m: Vec<f64> = (0..3).map(|k| p0[k] - c[k]).collect();
        let b: f64 = (0..3).map(|k| m[k] * dir[k]).sum();
        let cc: f64 = m.iter().map(|v| v * v).sum::<f64>() - 25.0;
        let t = -b - (b * b - cc).sqrt();
        let contact_x = p0[0] + dir[0] * t;
        assert!(
            contact_x < -1.0,
            "the contact is beyond the edge's end: x {contact_x}"
        );

        let as32 = |v: &[f64]| Vec3::new(v[0] as f32, v[1] as f32, v[2] as f32);
        let (start, dir32) = (as32(&p0), as32(&dir).normalize());
        match ball_box_sweep(start, dir32, len as f32, radius, half) {
            BallSweep::Hit { distance, normal } => {
                assert!((f64::from(distance) - t).abs() < 1e-3, "{distance} vs {t}");
                let centre = start + dir32 * distance;
                let want = (centre - Vec3::new(-1.0, 1.0, 1.0)).normalize();
                assert!((normal - want).length() < 1e-3, "{normal} vs {want}");
            }
            other => panic!("{other:?}"),
        }
    }
}
