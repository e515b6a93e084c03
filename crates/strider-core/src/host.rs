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
