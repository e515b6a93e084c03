//! What the host engine provides to a running rig (world queries) and what it gets back
//! besides the pose (debug drawing).
//!
//! The VM never owns physics: traces go through [`WorldQuery`], implemented by the host.
//! All positions here are in **world space**, centimetres; the trace nodes convert from
//! and to rig space with the frame's component-to-world transform.

use glam::Vec3;

/// A trace's first blocking hit, world space.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct TraceHit {
    /// Contact point, centimetres. For a sphere trace, the point on the surface touched.
    pub point: Vec3,
    /// Surface normal at the contact, unit length, pointing away from the surface.
    pub normal: Vec3,
    /// Distance travelled from the trace start to the hit, centimetres.
    pub distance: f32,
}

/// One line trace of a batch ([`WorldQuery::line_traces`]): the segment from `start` to
/// `end` (world space, centimetres).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct LineQuery {
    /// Where the segment starts.
    pub start: Vec3,
    /// Where the segment ends.
    pub end: Vec3,
}

/// One sphere trace of a batch ([`WorldQuery::sphere_traces`]): a sphere of `radius`
/// centimetres swept from `start` to `end` (world space, centimetres).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SphereQuery {
    /// Where the sphere's centre starts.
    pub start: Vec3,
    /// Where the sphere's centre would end.
    pub end: Vec3,
    /// The sphere's radius.
    pub radius: f32,
}

/// How many traces [`TraceColumns`] and [`HitColumns`] hold: as many as a batch of
/// characters the VM runs together.
pub const TRACE_COLUMNS: usize = 16;

/// Up to [`TRACE_COLUMNS`] traces of a batch, one array per coordinate (the layout the
/// VM keeps a batch's values in, and the one a world computes several traces per
/// instruction in): trace `k` runs from `(start[0][k], start[1][k], start[2][k])` to
/// `(end[0][k], end[1][k], end[2][k])`, world space, centimetres. For
/// [`WorldQuery::line_traces_in_columns`] and [`WorldQuery::sphere_traces_in_columns`].
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct TraceColumns {
    /// x, y and z of each trace's start.
    pub start: [[f32; TRACE_COLUMNS]; 3],
    /// x, y and z of each trace's end.
    pub end: [[f32; TRACE_COLUMNS]; 3],
    /// Each sphere's radius, centimetres (read by sphere traces only).
    pub radius: [f32; TRACE_COLUMNS],
}

impl TraceColumns {
    /// Trace `k` (`< TRACE_COLUMNS`) as a line trace.
    #[must_use]
    #[inline]
    pub fn line(&self, k: usize) -> LineQuery {
        LineQuery {
            start: Vec3::new(self.start[0][k], self.start[1][k], self.start[2][k]),
            end: Vec3::new(self.end[0][k], self.end[1][k], self.end[2][k]),
        }
    }

    /// Trace `k` (`< TRACE_COLUMNS`) as a sphere trace.
    #[must_use]
    #[inline]
    pub fn sphere(&self, k: usize) -> SphereQuery {
        let LineQuery { start, end } = self.line(k);
        SphereQuery {
            start,
            end,
            radius: self.radius[k],
        }
    }

    /// Writes the line trace `q` as trace `k` (`< TRACE_COLUMNS`); its radius is left as
    /// it is.
    #[inline]
    pub fn set_line(&mut self, k: usize, q: LineQuery) {
        [self.start[0][k], self.start[1][k], self.start[2][k]] = q.start.to_array();
        [self.end[0][k], self.end[1][k], self.end[2][k]] = q.end.to_array();
    }

    /// Writes the sphere trace `q` as trace `k` (`< TRACE_COLUMNS`).
    #[inline]
    pub fn set_sphere(&mut self, k: usize, q: SphereQuery) {
        self.set_line(
            k,
            LineQuery {
                start: q.start,
                end: q.end,
            },
        );
        self.radius[k] = q.radius;
    }
}

/// The answers to [`TraceColumns`], one array per component: where `hit[k]` is true,
/// trace `k` hit at `point` (centimetres, world space) with the unit `normal`, having
/// travelled `distance` centimetres, as [`TraceHit`]'s fields; where it is false, the trace
/// missed and the other entries of `k` mean nothing.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct HitColumns {
    /// Whether each trace hit.
    pub hit: [bool; TRACE_COLUMNS],
    /// x, y and z of each hit's point.
    pub point: [[f32; TRACE_COLUMNS]; 3],
    /// x, y and z of each hit's normal.
    pub normal: [[f32; TRACE_COLUMNS]; 3],
    /// How far each trace travelled to its hit.
    pub distance: [f32; TRACE_COLUMNS],
}

impl HitColumns {
    /// Writes `answer` as trace `k`'s (`< TRACE_COLUMNS`); a miss leaves the other entries
    /// of `k` as they are.
    #[inline]
    pub fn set(&mut self, k: usize, answer: Option<TraceHit>) {
        self.hit[k] = answer.is_some();
        if let Some(h) = answer {
            [self.point[0][k], self.point[1][k], self.point[2][k]] = h.point.to_array();
            [self.normal[0][k], self.normal[1][k], self.normal[2][k]] = h.normal.to_array();
            self.distance[k] = h.distance;
        }
    }

    /// Trace `k`'s answer (`k < TRACE_COLUMNS`).
    #[must_use]
    #[inline]
    pub fn get(&self, k: usize) -> Option<TraceHit> {
        self.hit[k].then(|| TraceHit {
            point: Vec3::new(self.point[0][k], self.point[1][k], self.point[2][k]),
            normal: Vec3::new(self.normal[0][k], self.normal[1][k], self.normal[2][k]),
            distance: self.distance[k],
        })
    }
}

/// Geometry queries a host answers for the rig. Implementations must be deterministic
/// (same query, same answer) for replays to be bit-identical.
pub trait WorldQuery {
    /// First hit of the segment `start → end`, or `None`.
    fn line_trace(&self, start: Vec3, end: Vec3) -> Option<TraceHit>;

    /// First hit of a sphere of `radius` swept from `start` to `end`, or `None`.
    /// `distance` is how far the sphere's centre travelled.
    fn sphere_trace(&self, start: Vec3, end: Vec3, radius: f32) -> Option<TraceHit>;

    /// Several line traces at once (a batch of characters tracing together): `hits[k]`
    /// becomes the answer to `queries[k]`, which must be [`WorldQuery::line_trace`]'s
    /// answer to it, bit for bit; entries of the longer slice past the shorter are left as
    /// they are. The default asks [`WorldQuery::line_trace`] one query at a time; a world
    /// can answer a batch faster.
    fn line_traces(&self, queries: &[LineQuery], hits: &mut [Option<TraceHit>]) {
        for (query, hit) in queries.iter().zip(hits) {
            *hit = self.line_trace(query.start, query.end);
        }
    }

    /// Several sphere traces at once (a batch of characters tracing together): `hits[k]`
    /// becomes the answer to `queries[k]`, which must be [`WorldQuery::sphere_trace`]'s
    /// answer to it, bit for bit; entries of the longer slice past the shorter are left
    /// as they are. The default asks [`WorldQuery::sphere_trace`] one query at a time; a
    /// world can answer a batch faster.
    fn sphere_traces(&self, queries: &[SphereQuery], hits: &mut [Option<TraceHit>]) {
        for (query, hit) in queries.iter().zip(hits) {
            *hit = self.sphere_trace(query.start, query.end, query.radius);
        }
    }

    /// The first `n` (at most [`TRACE_COLUMNS`]) line traces of `traces` at once, laid out
    /// in columns (a batch of characters tracing together, as the VM asks): trace `k`'s
    /// answer goes to entry `k` of `hits`, and must be [`WorldQuery::line_trace`]'s answer
    /// to it, bit for bit. Entries from `n` on may be written (a world may compute every
    /// column at once) and mean nothing afterwards. The default asks
    /// [`WorldQuery::line_traces`]; a world that computes in columns can answer without
    /// taking the traces apart.
    fn line_traces_in_columns(&self, traces: &TraceColumns, n: usize, hits: &mut HitColumns) {
        let n = n.min(TRACE_COLUMNS);
        let queries: [LineQuery; TRACE_COLUMNS] = std::array::from_fn(|k| traces.line(k));
        let mut answers = [None; TRACE_COLUMNS];
        self.line_traces(&queries[..n], &mut answers[..n]);
        for (k, answer) in answers.into_iter().enumerate().take(n) {
            hits.set(k, answer);
        }
    }

    /// The first `n` (at most [`TRACE_COLUMNS`]) sphere traces of `traces` at once, as
    /// [`WorldQuery::line_traces_in_columns`]: each answer [`WorldQuery::sphere_trace`]'s,
    /// bit for bit. The default asks [`WorldQuery::sphere_traces`].
    fn sphere_traces_in_columns(&self, traces: &TraceColumns, n: usize, hits: &mut HitColumns) {
        let n = n.min(TRACE_COLUMNS);
        let queries: [SphereQuery; TRACE_COLUMNS] = std::array::from_fn(|k| traces.sphere(k));
        let mut answers = [None; TRACE_COLUMNS];
        self.sphere_traces(&queries[..n], &mut answers[..n]);
        for (k, answer) in answers.into_iter().enumerate().take(n) {
            hits.set(k, answer);
        }
    }
}

/// A world with no geometry: every trace misses.
#[derive(Clone, Copy, Debug, Default)]
pub struct EmptyWorld;

impl WorldQuery for EmptyWorld {
    fn line_trace(&self, _start: Vec3, _end: Vec3) -> Option<TraceHit> {
        None
    }

    fn sphere_trace(&self, _start: Vec3, _end: Vec3, _radius: f32) -> Option<TraceHit> {
        None
    }
}

/// An RGBA colour, components in 0..=1.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DebugColor(pub [f32; 4]);

impl DebugColor {
    /// Opaque white.
    pub const WHITE: Self = Self([1.0, 1.0, 1.0, 1.0]);
    /// Opaque red.
    pub const RED: Self = Self([1.0, 0.0, 0.0, 1.0]);
    /// Opaque green.
    pub const GREEN: Self = Self([0.0, 1.0, 0.0, 1.0]);
    /// Opaque blue.
    pub const BLUE: Self = Self([0.0, 0.0, 1.0, 1.0]);
}

/// One debug-draw primitive, rig space, centimetres.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum DebugPrimitive {
    /// A point drawn `size` centimetres wide.
    Point {
        /// Position.
        position: Vec3,
        /// Diameter on screen, centimetres.
        size: f32,
        /// Colour.
        color: DebugColor,
    },
    /// A segment.
    Line {
        /// First end.
        start: Vec3,
        /// Second end.
        end: Vec3,
        /// Line width, centimetres.
        thickness: f32,
        /// Colour.
        color: DebugColor,
    },
    /// An arrow from `start` to `end` (head at `end`).
    Arrow {
        /// Tail.
        start: Vec3,
        /// Head.
        end: Vec3,
        /// Line width, centimetres.
        thickness: f32,
        /// Colour.
        color: DebugColor,
    },
    /// A wire sphere.
    Sphere {
        /// Centre.
        center: Vec3,
        /// Radius, centimetres.
        radius: f32,
        /// Colour.
        color: DebugColor,
    },
    /// A wire box: the cube `[-1, 1]³` scaled by `half_extents`, then placed by `transform`.
    Box {
        /// Placement of the box centre.
        transform: crate::Transform,
        /// Half size per local axis, centimetres.
        half_extents: Vec3,
        /// Colour.
        color: DebugColor,
    },
    /// Axes of a transform: X red, Y green, Z blue, each `size` centimetres long.
    Axes {
        /// The transform drawn.
        transform: crate::Transform,
        /// Axis length, centimetres.
        size: f32,
        /// Line width, centimetres.
        thickness: f32,
    },
}

/// Debug-draw output of one instance: a buffer refilled every frame.
///
/// Disabled, it records nothing and the draw nodes cost a branch. Enabled, it keeps its
/// capacity between frames, so after the first frames it no longer allocates.
#[derive(Clone, Debug, Default)]
pub struct DebugDraw {
    enabled: bool,
    primitives: Vec<DebugPrimitive>,
}

impl DebugDraw {
    /// Bytes of heap memory the buffer holds (its capacity, kept between frames).
    #[must_use]
    pub fn heap_bytes(&self) -> usize {
        self.primitives.capacity() * std::mem::size_of::<DebugPrimitive>()
    }

    /// A buffer that records when `enabled`.
    #[must_use]
    pub fn new(enabled: bool) -> Self {
        Self {
            enabled,
            primitives: Vec::new(),
        }
    }

    /// Whether draw nodes record anything.
    #[must_use]
    pub fn is_enabled(&self) -> bool {
        self.enabled
    }

    /// Turns recording on or off (clears the buffer).
    pub fn set_enabled(&mut self, enabled: bool) {
        self.enabled = enabled;
        self.primitives.clear();
    }

    /// Forgets last frame's primitives, keeping the memory.
    pub fn clear(&mut self) {
        self.primitives.clear();
    }

    /// Records a primitive if enabled.
    #[inline]
    pub fn push(&mut self, primitive: DebugPrimitive) {
        if self.enabled {
            self.primitives.push(primitive);
        }
    }

    /// The primitives recorded since the last [`DebugDraw::clear`].
    #[must_use]
    pub fn primitives(&self) -> &[DebugPrimitive] {
        &self.primitives
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A world that only answers one trace at a time: the plane z = 0, hit where a trace
    /// crosses it downwards (a sphere's lowest point), at the crossing.
    struct Floor;

    impl WorldQuery for Floor {
        fn line_trace(&self, start: Vec3, end: Vec3) -> Option<TraceHit> {
            self.sphere_trace(start, end, 0.0)
        }

        fn sphere_trace(&self, start: Vec3, end: Vec3, radius: f32) -> Option<TraceHit> {
            let (from, to) = (start.z - radius, end.z - radius);
            (from >= 0.0 && to < 0.0).then(|| {
                let t = from / (from - to);
                TraceHit {
                    point: start.lerp(end, t) - Vec3::Z * radius,
                    normal: Vec3::Z,
                    distance: start.distance(end) * t,
                }
            })
        }
    }

    #[test]
    fn columns_are_answered_by_default_as_each_trace_alone() {
        // Traces 0..16 fall from 10 cm to 10 − 1.5·k cm with radii 0.75·(k % 4): those
        // that reach the floor with their lowest point hit. The first 11 are asked.
        let mut traces = TraceColumns::default();
        for k in 0..TRACE_COLUMNS {
            let x = k as f32;
            [traces.start[0][k], traces.start[1][k], traces.start[2][k]] = [x, -x, 10.0];
            [traces.end[0][k], traces.end[1][k], traces.end[2][k]] = [x, 2.0, 10.0 - 1.5 * x];
            traces.radius[k] = 0.75 * (k % 4) as f32;
        }
        let n = 11;
        for sphere in [false, true] {
            let mut hits = HitColumns::default();
            if sphere {
                Floor.sphere_traces_in_columns(&traces, n, &mut hits);
            } else {
                Floor.line_traces_in_columns(&traces, n, &mut hits);
            }
            let mut hit = 0;
            for k in 0..n {
                let q = traces.sphere(k);
                let alone = if sphere {
                    Floor.sphere_trace(q.start, q.end, q.radius)
                } else {
                    Floor.line_trace(q.start, q.end)
                };
                assert_eq!(hits.get(k), alone, "trace {k}, sphere {sphere}");
                hit += usize::from(alone.is_some());
            }
            // Line traces: 10 − 1.5·k < 0 for k ≥ 7 (7..=10). Spheres: 10 − 1.5·k − r < 0
            // for 6 (r = 1.5) and 7..=10 too.
            let expected = if sphere { 5 } else { 4 };
            assert_eq!(hit, expected, "sphere {sphere}");
        }
    }

    #[test]
    fn a_column_holds_a_trace_and_its_answer() {
        let mut traces = TraceColumns::default();
        traces.start[1][3] = 2.0;
        traces.end[2][3] = -4.0;
        traces.radius[3] = 1.5;
        let sphere = SphereQuery {
            start: Vec3::new(0.0, 2.0, 0.0),
            end: Vec3::new(0.0, 0.0, -4.0),
            radius: 1.5,
        };
        assert_eq!(traces.sphere(3), sphere);
        let mut written = TraceColumns::default();
        written.set_sphere(3, sphere);
        assert_eq!(written, traces);
        written.set_line(
            3,
            LineQuery {
                start: Vec3::X,
                end: Vec3::Y,
            },
        );
        assert_eq!(
            (written.start[0][3], written.end[1][3], written.radius[3]),
            (1.0, 1.0, 1.5)
        );
        let answer = TraceHit {
            point: Vec3::new(1.0, 2.0, 3.0),
            normal: Vec3::Y,
            distance: 4.0,
        };
        let mut hits = HitColumns::default();
        hits.set(5, Some(answer));
        assert_eq!(
            (hits.point[2][5], hits.normal[1][5], hits.distance[5]),
            (3.0, 1.0, 4.0)
        );
        assert_eq!(hits.get(5), Some(answer));
        hits.set(5, None);
        assert_eq!(hits.get(5), None);
        assert_eq!(hits.get(4), None);
    }
}
