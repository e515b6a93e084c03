//! The demo world: static shapes described in RON, answering line and sphere traces through
//! parry3d.
//!
//! # Space and units
//!
//! Everything here is **world space**: +Z up, centimetres; yaw angles are in degrees about
//! +Z. Yaw 0 faces world +Y and a positive yaw turns counter-clockwise seen from above:
//! `Rz(+90°)` maps +Y to −X, so a shape with yaw 90° has its "forward" along −X. The
//! forward direction of a yaw `ψ` is `(−sin ψ, cos ψ, 0)` ([`yaw_direction`]).
//!
//! # File format
//!
//! ```ron
//! (
//!     shapes: [
//!         Ground(height: 0.0),
//!         Box(center: (300.0, 0.0, 50.0), half_extents: (50.0, 200.0, 50.0), yaw: 0.0),
//!         Ramp(start: (0.0, 500.0, 0.0), yaw: 0.0, angle: 20.0, length: 300.0, width: 200.0),
//!         Stairs(start: (0.0, 900.0, 0.0), yaw: 0.0, width: 200.0, steps: 8, rise: 15.0,
//!                run: 30.0, landing: 150.0),
//!         Platform(center: (0.0, 0.0), half_size: (100.0, 100.0), top: 20.0),
//!         Heightfield(origin: (-2000.0, -2000.0, 0.0), size: (4000.0, 4000.0),
//!                     cells: (80, 80), waves: [(amplitude: 3.0, wavelength: 250.0)]),
//!     ],
//! )
//! ```
//!
//! Every shape is solid: a trace starting inside one hits it at distance 0. The
//! heightfield is the exception (a surface, hit from above).
//!
//! # Queries
//!
//! Traces loop over the shapes and keep the nearest hit (the first shape in the list wins
//! a tie), so answers are deterministic. Each shape's bounding box is computed once; a
//! trace skips every shape whose box its own swept box misses, so only the few shapes near
//! a trace pay for an exact query (a stair flight is one box per step). Demo worlds hold
//! tens of shapes, where this linear pass over boxes costs less than descending a tree; a
//! world with thousands would put them in parry's BVH (`parry3d::partitioning::Bvh`).

use std::fmt;
use std::path::{Path, PathBuf};
use std::sync::Arc;

use glam::{Quat, Vec3, Vec3A, Vec4};
use parry3d::bounding_volume::{Aabb, BoundingVolume};
use parry3d::math::Pose;
use parry3d::query::details::local_ray_intersection_with_triangle;
use parry3d::query::{Ray, ShapeCastOptions, cast_shapes};
use parry3d::shape::{Ball, Shape, SharedShape, TriMesh};
use serde::Deserialize;
use serde::de::{self, Deserializer, SeqAccess, Visitor};
use strider_core::{
    HitColumns, LineQuery, SphereQuery, TRACE_COLUMNS, TraceColumns, TraceHit, WorldQuery,
    all_finite, load_vec3,
};

use crate::sweep::{
    BallSweep, Facet, HullTriangle, Plane, ball_box_sweep, ball_half_space_sweep, ball_hull_sweep,
    ball_reach, ball_triangles_sweep, hull_facets,
};

/// How far [`World::ground_height`] looks below its start point, centimetres.
pub const GROUND_SEARCH_DEPTH: f32 = 100_000.0;

/// The largest number of heightfield vertices accepted (`(cols + 1) · (rows + 1)`).
pub const MAX_HEIGHTFIELD_VERTICES: usize = 1_000_000;

/// Forward direction (world XY, unit length, z = 0) of a yaw in degrees: yaw 0 is +Y,
/// positive yaw turns counter-clockwise seen from above (90° is −X).
#[must_use]
pub fn yaw_direction(yaw_deg: f32) -> Vec3 {
    let (s, c) = yaw_deg.to_radians().sin_cos();
    Vec3::new(-s, c, 0.0)
}

/// The yaw in degrees, in (−180°, 180°], of a world XY direction (the inverse of
/// [`yaw_direction`]); 0 for a zero vector.
#[must_use]
pub fn direction_yaw(x: f32, y: f32) -> f32 {
    if x == 0.0 && y == 0.0 {
        0.0
    } else {
        (-x).atan2(y).to_degrees()
    }
}

/// One sine wave of a generated heightfield:
/// `amplitude · sin(2π · (d · (p − origin)) / wavelength + phase)`, where `d` is the unit
/// direction of `heading` ([`yaw_direction`]) and `p` the world XY position.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Wave {
    /// Peak height above the origin plane, centimetres.
    pub amplitude: f32,
    /// Distance between crests, centimetres (> 0).
    pub wavelength: f32,
    /// Direction the crests travel along, degrees (yaw convention: 0 = +Y). Default 0.
    #[serde(default)]
    pub heading: f32,
    /// Phase offset, degrees. Default 0.
    #[serde(default)]
    pub phase: f32,
}

/// One shape of a world. All positions are world space, centimetres; yaw and angles are
/// degrees (yaw 0 = the shape's forward is +Y, positive counter-clockwise from above).
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub enum ShapeDesc {
    /// An infinite flat floor (a half-space) whose top is at z = `height`; solid below.
    Ground {
        /// Height of the floor's top, centimetres.
        height: f32,
    },
    /// A solid box.
    Box {
        /// Centre, world space, centimetres.
        center: (f32, f32, f32),
        /// Half size along the box's local X (side), Y (forward) and Z (up), centimetres.
        half_extents: (f32, f32, f32),
        /// Rotation about +Z, degrees. Default 0.
        #[serde(default)]
        yaw: f32,
    },
    /// A solid wedge whose top is a slope: it starts at ground level along its near edge
    /// (centred on `start`) and rises along its forward direction to
    /// `start.z + length · tan(angle)` at the far edge, where it ends with a vertical face.
    Ramp {
        /// Centre of the bottom (near) edge, centimetres.
        start: (f32, f32, f32),
        /// Direction the ramp rises towards, degrees. Default 0 (+Y).
        #[serde(default)]
        yaw: f32,
        /// Slope angle, degrees, in (0, 80).
        angle: f32,
        /// Horizontal length of the slope, centimetres.
        length: f32,
        /// Width across the slope, centimetres.
        width: f32,
    },
    /// A flight of solid steps rising along the forward direction from `start` (the centre
    /// of the first riser's bottom edge): step `i` (from 0) covers forward distances
    /// `[i · run, (i + 1) · run]` and its top is at `start.z + (i + 1) · rise`. An optional
    /// landing of depth `landing` continues the top step.
    Stairs {
        /// Centre of the first riser's bottom edge, centimetres.
        start: (f32, f32, f32),
        /// Direction the stairs rise towards, degrees. Default 0 (+Y).
        #[serde(default)]
        yaw: f32,
        /// Width across the stairs, centimetres.
        width: f32,
        /// Number of steps (1..=1000).
        steps: u32,
        /// Height of each step, centimetres.
        rise: f32,
        /// Depth of each step, centimetres.
        run: f32,
        /// Depth of the landing after the last step, centimetres. Default 0 (none).
        #[serde(default)]
        landing: f32,
    },
    /// A raised box given by its top: an alias of [`ShapeDesc::Box`] whose top face is at
    /// z = `top` and which extends `depth` below it.
    Platform {
        /// Centre of the top face in world XY, centimetres.
        center: (f32, f32),
        /// Half size along the platform's local X and Y, centimetres.
        half_size: (f32, f32),
        /// Height of the top face, centimetres.
        top: f32,
        /// Rotation about +Z, degrees. Default 0.
        #[serde(default)]
        yaw: f32,
        /// Thickness below the top, centimetres. Default 100.
        #[serde(default = "default_platform_depth")]
        depth: f32,
    },
    /// Uneven ground: a grid of `cells.0 × cells.1` cells covering `size` from `origin`
    /// (the minimum X/Y corner), as a triangle mesh (a surface, hit from above).
    ///
    /// The height of the vertex at column `i`, row `j` (world XY
    /// `origin.xy + (i · size.x / cells.0, j · size.y / cells.1)`) is
    /// `origin.z + heights[j · (cells.0 + 1) + i] + Σ waves`, where `heights` is optional
    /// (empty = all 0, otherwise exactly `(cells.0 + 1) · (cells.1 + 1)` values, X fastest)
    /// and each [`Wave`] is evaluated at the vertex. No randomness: the same description
    /// always gives the same surface.
    Heightfield {
        /// Minimum corner in XY, and the base height, centimetres.
        origin: (f32, f32, f32),
        /// Extent along X and Y, centimetres.
        size: (f32, f32),
        /// Number of cells along X and Y (each ≥ 1).
        cells: (u32, u32),
        /// Explicit vertex heights above `origin.z`, centimetres, X fastest. Default none.
        #[serde(default)]
        heights: Vec<f32>,
        /// Sine waves added to the heights. Default none.
        #[serde(default)]
        waves: Vec<Wave>,
    },
}

fn default_platform_depth() -> f32 {
    100.0
}

/// A solid box of a world shape, world space: what the collision shape is and what a
/// viewer draws.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SolidBox {
    /// Centre, world, cm.
    pub center: Vec3,
    /// Half sizes along the box's own X, Y, Z, cm.
    pub half_extents: Vec3,
    /// The box's rotation (a yaw about +Z).
    pub rotation: Quat,
}

impl ShapeDesc {
    /// The solid boxes of a `Box`, a `Platform` or a `Stairs` shape (one per step, the last
    /// running on through the landing), as the world collides with them; nothing for the
    /// other shapes. For a shape that [`ShapeDesc::validate`] accepts.
    pub fn solid_boxes(&self) -> impl Iterator<Item = SolidBox> + '_ {
        let (count, start, yaw) = match *self {
            ShapeDesc::Box { center, yaw, .. } => (1, center, yaw),
            ShapeDesc::Platform { center, yaw, .. } => (1, (center.0, center.1, 0.0), yaw),
            ShapeDesc::Stairs {
                start, yaw, steps, ..
            } => (steps, start, yaw),
            _ => (0, (0.0, 0.0, 0.0), 0.0),
        };
        let rotation = Quat::from_rotation_z(yaw.to_radians());
        (0..count).map(move |i| match *self {
            ShapeDesc::Platform {
                half_size,
                top,
                depth,
                ..
            } => SolidBox {
                center: Vec3::new(start.0, start.1, top - depth * 0.5),
                half_extents: Vec3::new(half_size.0, half_size.1, depth * 0.5),
                rotation,
            },
            ShapeDesc::Stairs {
                width,
                steps,
                rise,
                run,
                landing,
                ..
            } => {
                let top = (i + 1) as f32 * rise;
                let near = i as f32 * run;
                // The last step runs on through the landing, so the landing has no seam.
                let far = if i + 1 == steps {
                    (i + 1) as f32 * run + landing
                } else {
                    (i + 1) as f32 * run
                };
                let local = Vec3::new(0.0, (near + far) * 0.5, top * 0.5);
                SolidBox {
                    center: v3(start) + rotation * local,
                    half_extents: Vec3::new(width * 0.5, (far - near) * 0.5, top * 0.5),
                    rotation,
                }
            }
            ShapeDesc::Box { half_extents, .. } => SolidBox {
                center: v3(start),
                half_extents: v3(half_extents),
                rotation,
            },
            _ => SolidBox {
                center: Vec3::ZERO,
                half_extents: Vec3::ZERO,
                rotation,
            },
        })
    }

    /// The six corners of a `Ramp`, in the ramp's frame (X across, Y forward and rising, Z
    /// up, origin at the centre of its near edge: rotate them by `yaw` about +Z and add
    /// `start` for world space), cm: near edge left and right, far bottom edge left and
    /// right, far top edge left and right. `None` for other shapes.
    #[must_use]
    pub fn ramp_corners(&self) -> Option<[Vec3; 6]> {
        let ShapeDesc::Ramp {
            angle,
            length,
            width,
            ..
        } = *self
        else {
            return None;
        };
        let height = length * angle.to_radians().tan();
        let hw = width * 0.5;
        Some([
            Vec3::new(-hw, 0.0, 0.0),
            Vec3::new(hw, 0.0, 0.0),
            Vec3::new(-hw, length, 0.0),
            Vec3::new(hw, length, 0.0),
            Vec3::new(-hw, length, height),
            Vec3::new(hw, length, height),
        ])
    }

    /// Vertex `(i, j)` of a `Heightfield`'s grid, world, cm: `origin.xy + (i · size.x /
    /// cells.0, j · size.y / cells.1)` at height `origin.z + heights[j · (cells.0 + 1) + i]
    /// + Σ waves` (indices past the grid are clamped to its edge). `None` for other shapes.
    #[must_use]
    pub fn heightfield_vertex(&self, i: u32, j: u32) -> Option<Vec3> {
        let ShapeDesc::Heightfield {
            origin,
            size,
            cells,
            ref heights,
            ref waves,
        } = *self
        else {
            return None;
        };
        let (cx, cy) = (cells.0.max(1), cells.1.max(1));
        let (i, j) = (i.min(cx), j.min(cy));
        let x = origin.0 + size.0 * i as f32 / cx as f32;
        let y = origin.1 + size.1 * j as f32 / cy as f32;
        let explicit = heights
            .get(j as usize * (cx as usize + 1) + i as usize)
            .copied()
            .unwrap_or(0.0);
        let z = origin.2 + explicit + wave_height(waves, (origin.0, origin.1), x, y);
        Some(Vec3::new(x, y, z))
    }

    /// The parry3d shapes this description collides as, placed in world space (cm): a
    /// half-space for the ground, a cuboid per solid box (a stair flight's steps, a
    /// platform), a convex hull for a ramp, a triangle mesh for a heightfield (two triangles
    /// per cell, counter-clockwise seen from above, so normals point up). An error message
    /// when parry3d cannot build one (a degenerate ramp).
    pub fn collision_shapes(&self) -> Result<Vec<(Pose, SharedShape)>, String> {
        let shapes = match self {
            ShapeDesc::Ground { height } => vec![(
                Pose::from_translation(Vec3::new(0.0, 0.0, *height)),
                SharedShape::halfspace(Vec3::Z),
            )],
            ShapeDesc::Box { .. } | ShapeDesc::Stairs { .. } | ShapeDesc::Platform { .. } => self
                .solid_boxes()
                .map(|b| {
                    let h = b.half_extents;
                    (
                        Pose::from_parts(b.center, b.rotation),
                        SharedShape::cuboid(h.x, h.y, h.z),
                    )
                })
                .collect(),
            ShapeDesc::Ramp { start, yaw, .. } => {
                let local = self.ramp_corners().unwrap_or_default();
                let shape = SharedShape::convex_hull(&local)
                    .ok_or("the ramp is degenerate (check length, width and angle)")?;
                vec![(pose(v3(*start), *yaw), shape)]
            }
            ShapeDesc::Heightfield { cells, .. } => {
                let (nx, ny) = (cells.0 as usize, cells.1 as usize);
                let mut vertices = Vec::with_capacity((nx + 1) * (ny + 1));
                for j in 0..=cells.1 {
                    for i in 0..=cells.0 {
                        vertices.extend(self.heightfield_vertex(i, j));
                    }
                }
                let mut indices = Vec::with_capacity(nx * ny * 2);
                for j in 0..ny {
                    for i in 0..nx {
                        let v00 = (j * (nx + 1) + i) as u32;
                        let v10 = v00 + 1;
                        let v01 = v00 + nx as u32 + 1;
                        let v11 = v01 + 1;
                        indices.push([v00, v10, v11]);
                        indices.push([v00, v11, v01]);
                    }
                }
                let mesh = TriMesh::new(vertices, indices).map_err(|e| format!("{e:?}"))?;
                vec![(Pose::IDENTITY, SharedShape::new(mesh))]
            }
        };
        Ok(shapes)
    }

    /// The variant's name as written in RON.
    #[must_use]
    pub fn kind(&self) -> &'static str {
        match self {
            ShapeDesc::Ground { .. } => "Ground",
            ShapeDesc::Box { .. } => "Box",
            ShapeDesc::Ramp { .. } => "Ramp",
            ShapeDesc::Stairs { .. } => "Stairs",
            ShapeDesc::Platform { .. } => "Platform",
            ShapeDesc::Heightfield { .. } => "Heightfield",
        }
    }

    /// Checks the values (finite, positive sizes, counts in range). The message says what
    /// is wrong and how to fix it.
    pub fn validate(&self) -> Result<(), String> {
        let finite = |name: &str, values: &[f32]| -> Result<(), String> {
            if values.iter().all(|v| v.is_finite()) {
                Ok(())
            } else {
                Err(format!("`{name}` must be finite numbers"))
            }
        };
        let positive = |name: &str, values: &[f32]| -> Result<(), String> {
            if values.iter().all(|v| v.is_finite() && *v > 0.0) {
                Ok(())
            } else {
                Err(format!("`{name}` must be greater than 0 (centimetres)"))
            }
        };
        match self {
            ShapeDesc::Ground { height } => finite("height", &[*height]),
            ShapeDesc::Box {
                center,
                half_extents,
                yaw,
            } => {
                finite("center", &[center.0, center.1, center.2])?;
                positive(
                    "half_extents",
                    &[half_extents.0, half_extents.1, half_extents.2],
                )?;
                finite("yaw", &[*yaw])
            }
            ShapeDesc::Ramp {
                start,
                yaw,
                angle,
                length,
                width,
            } => {
                finite("start", &[start.0, start.1, start.2])?;
                finite("yaw", &[*yaw])?;
                if !(angle.is_finite() && *angle > 0.0 && *angle < 80.0) {
                    return Err("`angle` must be between 0 and 80 degrees (exclusive)".into());
                }
                positive("length", &[*length])?;
                positive("width", &[*width])
            }
            ShapeDesc::Stairs {
                start,
                yaw,
                width,
                steps,
                rise,
                run,
                landing,
            } => {
                finite("start", &[start.0, start.1, start.2])?;
                finite("yaw", &[*yaw])?;
                positive("width", &[*width])?;
                if !(1..=1000).contains(steps) {
                    return Err("`steps` must be between 1 and 1000".into());
                }
                positive("rise", &[*rise])?;
                positive("run", &[*run])?;
                if !(landing.is_finite() && *landing >= 0.0) {
                    return Err("`landing` must be 0 (no landing) or more centimetres".into());
                }
                Ok(())
            }
            ShapeDesc::Platform {
                center,
                half_size,
                top,
                yaw,
                depth,
            } => {
                finite("center", &[center.0, center.1])?;
                positive("half_size", &[half_size.0, half_size.1])?;
                finite("top", &[*top])?;
                finite("yaw", &[*yaw])?;
                positive("depth", &[*depth])
            }
            ShapeDesc::Heightfield {
                origin,
                size,
                cells,
                heights,
                waves,
            } => {
                finite("origin", &[origin.0, origin.1, origin.2])?;
                positive("size", &[size.0, size.1])?;
                if cells.0 == 0 || cells.1 == 0 {
                    return Err("`cells` must be at least (1, 1)".into());
                }
                let vertices = (cells.0 as usize + 1).saturating_mul(cells.1 as usize + 1);
                if vertices > MAX_HEIGHTFIELD_VERTICES {
                    return Err(format!(
                        "`cells` gives {vertices} vertices; use at most \
                         {MAX_HEIGHTFIELD_VERTICES} (fewer, larger cells)"
                    ));
                }
                if !heights.is_empty() && heights.len() != vertices {
                    return Err(format!(
                        "`heights` has {} values but `cells: ({}, {})` needs {vertices} \
                         ((cells.0 + 1) · (cells.1 + 1), X fastest), or leave it out",
                        heights.len(),
                        cells.0,
                        cells.1
                    ));
                }
                finite("heights", heights)?;
                for wave in waves {
                    finite("waves.amplitude", &[wave.amplitude])?;
                    positive("waves.wavelength", &[wave.wavelength])?;
                    finite("waves.heading", &[wave.heading])?;
                    finite("waves.phase", &[wave.phase])?;
                }
                Ok(())
            }
        }
    }
}

/// A world description: the shapes, in the order traces prefer them on ties.
#[derive(Clone, Debug, Default, PartialEq, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct WorldDesc {
    /// The shapes. Each is checked while the file is read, so an error points at it.
    #[serde(deserialize_with = "deserialize_checked_seq")]
    pub shapes: Vec<ShapeDesc>,
}

/// An element of a list that is validated as soon as it is read, so that a parse error
/// carries the position of the faulty element (shapes of a world, segments of a timeline).
pub(crate) trait CheckedElement: Sized {
    /// What the list holds, for messages: "shape", "segment".
    const NOUN: &'static str;
    /// The element's variant name as written in RON.
    fn kind(&self) -> &'static str;
    /// Checks the element's values; the message names the field and the range.
    fn validate(&self) -> Result<(), String>;
}

impl CheckedElement for ShapeDesc {
    const NOUN: &'static str = "shape";
    fn kind(&self) -> &'static str {
        ShapeDesc::kind(self)
    }
    fn validate(&self) -> Result<(), String> {
        ShapeDesc::validate(self)
    }
}

/// Reads a list of `T`, validating each element as soon as it is read; an invalid one is
/// reported as `Kind (noun index): message`.
pub(crate) fn deserialize_checked_seq<'de, D, T>(deserializer: D) -> Result<Vec<T>, D::Error>
where
    D: Deserializer<'de>,
    T: CheckedElement + Deserialize<'de>,
{
    struct CheckedVisitor<T>(std::marker::PhantomData<T>);
    impl<'de, T: CheckedElement + Deserialize<'de>> Visitor<'de> for CheckedVisitor<T> {
        type Value = Vec<T>;
        fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
            write!(f, "a list of {}s", T::NOUN)
        }
        fn visit_seq<A: SeqAccess<'de>>(self, mut seq: A) -> Result<Self::Value, A::Error> {
            let mut items = Vec::new();
            while let Some(item) = seq.next_element::<T>()? {
                if let Err(message) = item.validate() {
                    return Err(de::Error::custom(format!(
                        "{} ({} {}): {message}",
                        item.kind(),
                        T::NOUN,
                        items.len()
                    )));
                }
                items.push(item);
            }
            Ok(items)
        }
    }
    deserializer.deserialize_seq(CheckedVisitor(std::marker::PhantomData))
}

/// An error reading or building a world.
#[derive(Debug, thiserror::Error)]
pub enum WorldError {
    /// The file could not be read.
    #[error("{}: cannot read the world file: {source}", path.display())]
    Io {
        /// The file.
        path: PathBuf,
        /// The I/O error.
        #[source]
        source: std::io::Error,
    },
    /// The text is not a valid world description.
    #[error("{origin}:{line}:{col}: error: {message}\n  hint: {help}")]
    Parse {
        /// The file name (or `<string>`).
        origin: String,
        /// Line, from 1.
        line: usize,
        /// Column, from 1.
        col: usize,
        /// What is wrong.
        message: String,
        /// How to fix it.
        help: String,
    },
    /// A shape has invalid values.
    #[error("shape {index} ({kind}): {message}")]
    InvalidShape {
        /// Index of the shape in [`WorldDesc::shapes`].
        index: usize,
        /// Its variant name.
        kind: &'static str,
        /// What is wrong and how to fix it.
        message: String,
    },
    /// parry3d rejected generated geometry (for instance a degenerate heightfield).
    #[error("shape {index} ({kind}): cannot build the collision shape: {message}")]
    Geometry {
        /// Index of the shape in [`WorldDesc::shapes`].
        index: usize,
        /// Its variant name.
        kind: &'static str,
        /// parry3d's message.
        message: String,
    },
}

/// A sweep's delta (cm, world space) with its unit direction and its length (cm).
#[derive(Clone, Copy)]
struct Along {
    delta: Vec3,
    dir: Vec3,
    length: f32,
}

/// A hit of a swept capsule or sphere, world space (used by the mover).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct SweepHit {
    /// Distance travelled along the sweep direction before contact, centimetres.
    pub distance: f32,
    /// Surface normal, unit length, away from the surface.
    pub normal: Vec3,
}

/// A built world: collision shapes placed in world space, answering traces.
#[derive(Clone)]
pub struct World {
    desc: WorldDesc,
    colliders: Vec<Collider>,
    /// The colliders' bounds, four to a [`Quad`] in the colliders' order: what a trace
    /// scans to find the colliders near it.
    quads: Vec<Quad>,
    /// Whether any collider has bounds: else a trace need not compute its own.
    bounded: bool,
    /// The half-spaces among the colliders (the ground under most traces), with their
    /// indices: what every trace and sweep tests first.
    half_spaces: Vec<HalfSpace>,
}

/// A half-space collider: a point on its plane and its unit outward normal (world space),
/// and its index among the world's colliders.
#[derive(Clone, Copy, Debug)]
struct HalfSpace {
    point: Vec3,
    normal: Vec3,
    index: usize,
}

/// The bounds of four consecutive colliders laid out by axis, so that testing a box
/// against all four is a few vector comparisons (a trace in a world of a flight of stairs
/// tests twenty boxes). Written by hand: parry3d's bounding-volume tree is built for
/// thousands of shapes and walks nodes one by one.
#[derive(Clone, Copy, Debug)]
struct Quad {
    /// Minimum corner per axis (x, y, z), one lane per collider. A missing collider (past
    /// the last) or a half-space has `+∞`, so nothing is near it.
    lo: [Vec4; 3],
    /// Maximum corner per axis, one lane per collider (`−∞` for a missing one or a
    /// half-space, which the traces test on their own).
    hi: [Vec4; 3],
}

impl Quad {
    /// Bits `k` of the four colliders whose bounds meet `reach` (boxes touching on a face
    /// count, as in parry3d's `Aabb::intersects`). A half-space is never near.
    #[inline(always)]
    fn near(&self, reach: &Aabb) -> u32 {
        let (low, high) = (reach.mins, reach.maxs);
        let meets = |axis: usize, low: f32, high: f32| {
            self.lo[axis].cmple(Vec4::splat(high)) & Vec4::splat(low).cmple(self.hi[axis])
        };
        let all = meets(0, low.x, high.x) & meets(1, low.y, high.y) & meets(2, low.z, high.z);
        all.bitmask()
    }
}

/// One collision shape placed in the world, with what traces need to know about it before
/// asking it anything.
#[derive(Clone)]
struct Collider {
    pose: Pose,
    shape: SharedShape,
    /// What the shape is, for the sweeps that have a closed form.
    form: Form,
}

/// The bounded colliders of a [`World`] whose bounds meet a box, with their indices, in
/// the colliders' order.
struct Near<'a> {
    world: &'a World,
    reach: Aabb,
    /// The next quad to scan.
    quad: usize,
    /// The colliders of the quad before `quad` not yet returned.
    bits: u32,
}

impl<'a> Iterator for Near<'a> {
    type Item = (usize, &'a Collider);

    #[inline(always)]
    fn next(&mut self) -> Option<(usize, &'a Collider)> {
        while self.bits == 0 {
            self.bits = self.world.quads.get(self.quad)?.near(&self.reach);
            self.quad += 1;
        }
        let k = (self.quad - 1) * 4 + self.bits.trailing_zeros() as usize;
        self.bits &= self.bits - 1;
        Some((k, self.world.colliders.get(k)?))
    }
}

/// The kinds of shape a ball's sweep is answered for in closed form ([`crate::sweep`]).
#[derive(Clone)]
enum Form {
    /// A half-space: a point on its plane and its unit outward normal, world space.
    HalfSpace { point: Vec3, normal: Vec3 },
    /// A box with these half extents (cm) in its own frame (the collider's pose).
    Box { half: Vec3 },
    /// A triangle mesh (the heightfield): its triangles near the sweep, found by the
    /// heightfield's cells when it has them and the sweep covers few, else through the
    /// mesh's own tree; and each triangle's unit normal ([`Facet::normal_of`]), by the
    /// mesh's triangle numbers.
    Mesh {
        grid: Option<Grid>,
        normals: Arc<[Option<Vec3>]>,
    },
    /// A convex hull (a ramp), in its own frame: its surface as triangles, each with its
    /// unit outward normal (`None` for a degenerate one), and its faces' planes (unit
    /// outward normal, offset).
    Hull {
        triangles: Arc<[HullTriangle]>,
        planes: Arc<[Plane]>,
    },
    /// Anything else: parry3d's general cast.
    Other,
}

impl Collider {
    /// A ball of `radius` swept from `start` along the unit `dir` for `length` (world
    /// space), in closed form: `Some(hit or miss)`, or `None` when this shape has no closed
    /// form or the ball starts overlapping it (then parry3d's cast answers).
    #[inline]
    fn ball_sweep(
        &self,
        start: Vec3,
        dir: Vec3,
        length: f32,
        radius: f32,
        stop_at_penetration: bool,
    ) -> Option<Option<SweepHit>> {
        // A half-space (the ground under most traces) inline; the bounded shapes out of line.
        if let Form::HalfSpace { point, normal } = self.form {
            return Some(
                ball_half_space_sweep(
                    start,
                    dir,
                    length,
                    radius,
                    point,
                    normal,
                    stop_at_penetration,
                )
                .map(|distance| SweepHit { distance, normal }),
            );
        }
        self.ball_sweep_bounded(start, dir, length, radius)
    }

    /// [`Collider::ball_sweep`] for the shapes other than a half-space (with
    /// `stop_at_penetration`: their closed forms leave a ball starting in them to parry3d).
    #[inline(never)]
    fn ball_sweep_bounded(
        &self,
        start: Vec3,
        dir: Vec3,
        length: f32,
        radius: f32,
    ) -> Option<Option<SweepHit>> {
        match &self.form {
            Form::HalfSpace { .. } | Form::Other => None,
            &Form::Box { half } => {
                let (local_start, local_dir) = self.to_local(start, dir);
                self.found(ball_box_sweep(local_start, local_dir, length, radius, half))
            }
            Form::Mesh { grid, normals } => {
                let mesh = self.shape.as_trimesh()?;
                let (start, dir) = self.to_local(start, dir);
                let reach = ball_reach(start, start + dir * length, radius);
                // The normals are the mesh's, triangle by triangle (built with it).
                let facet = |i: u32| {
                    let t = mesh.triangle(i);
                    Facet {
                        corners: [t.a, t.b, t.c],
                        normal: normals[i as usize],
                    }
                };
                self.found(match grid.and_then(|g| g.cells_under(&reach)) {
                    Some(cells) => {
                        let near = cells.triangles().map(facet);
                        ball_triangles_sweep(start, dir, length, radius, near)
                    }
                    None => {
                        let near = mesh.bvh().intersect_aabb(&reach).map(facet);
                        ball_triangles_sweep(start, dir, length, radius, near)
                    }
                })
            }
            Form::Hull { triangles, planes } => {
                let (local_start, local_dir) = self.to_local(start, dir);
                self.found(ball_hull_sweep(
                    local_start,
                    local_dir,
                    length,
                    radius,
                    triangles,
                    planes,
                ))
            }
        }
    }

    /// `shape` (at `start`, not rotated) swept along `along` against this shape by
    /// parry3d's general cast, keeping `skin` from its surface: the hit, if any, with a
    /// unit normal (`−dir` where the cast gives none). Out of line: the closed forms answer
    /// the common traces.
    #[cold]
    #[inline(never)]
    fn cast(
        &self,
        shape: &dyn Shape,
        start: Vec3,
        along: Along,
        skin: f32,
        stop_at_penetration: bool,
    ) -> Option<SweepHit> {
        let options = ShapeCastOptions {
            max_time_of_impact: along.length,
            target_distance: skin,
            stop_at_penetration,
            compute_impact_geometry_on_penetration: true,
        };
        let hit = cast_shapes(
            &Pose::from_translation(start),
            along.dir,
            shape,
            &self.pose,
            Vec3::ZERO,
            self.shape.as_ref(),
            options,
        )
        .ok()??;
        let mut normal = -hit.normal1;
        if !normal.is_finite() || normal.length_squared() < 1e-12 {
            normal = -along.dir;
        } else {
            normal = normal.normalize();
        }
        Some(SweepHit {
            distance: hit.time_of_impact.max(0.0),
            normal,
        })
    }

    /// The ray from `ray.origin` along the unit `ray.dir` for `length` against this solid
    /// bounded shape (world space), by parry3d: the distance to the first hit and the
    /// normal there, zero for a ray starting inside. (Line traces test the half-spaces on
    /// their own, with [`ray_half_space`].) A heightfield's triangles are found by the
    /// cells under the ray, as its sweeps find them ([`Collider::ray_by_cells`]).
    #[inline]
    fn ray(&self, ray: &Ray, length: f32) -> Option<(f32, Vec3)> {
        // Out of line, so that the common shapes' rays stay small enough to inline.
        if let Form::Mesh {
            grid: Some(grid), ..
        } = &self.form
            && let Some(found) = self.ray_by_cells(grid, ray, length)
        {
            return found;
        }
        self.shape
            .cast_ray_and_get_normal(&self.pose, ray, length, true)
            .map(|hit| (hit.time_of_impact, hit.normal))
    }

    /// [`Collider::ray`] for a heightfield whose cells under the ray are at most
    /// [`MAX_GRID_CELLS`]: each of their triangles tested with parry3d's own ray-triangle
    /// test, in the shape's frame as parry3d's mesh cast tests it, the nearest kept (of
    /// equal distances the first, by cell). The mesh's tree, which the cast walks node by
    /// node, finds the same triangles for several times the work: a locomotion graph's line
    /// traces are short and cross one or two cells. A hit at the segment's very end counts,
    /// as on the other shapes' closed forms (parry3d's mesh cast, which answered these
    /// traces before, takes only hits short of it). `grid` is the heightfield's; `None`
    /// for more cells.
    #[inline(never)]
    fn ray_by_cells(&self, grid: &Grid, ray: &Ray, length: f32) -> Option<Option<(f32, Vec3)>> {
        let mesh = self.shape.as_trimesh()?;
        let local = ray.inverse_transform_by(&self.pose);
        let end = local.origin + local.dir * length;
        let cells = grid.cells_under(&Aabb::new(local.origin.min(end), local.origin.max(end)))?;
        let mut best: Option<(f32, Vec3)> = None;
        for i in cells.triangles() {
            let t = mesh.triangle(i);
            if let Some((hit, _)) = local_ray_intersection_with_triangle(t.a, t.b, t.c, &local)
                && hit.time_of_impact <= length
                && best.is_none_or(|(b, _)| hit.time_of_impact < b)
            {
                best = Some((hit.time_of_impact, hit.normal));
            }
        }
        Some(best.map(|(distance, normal)| (distance, self.pose.rotation * normal)))
    }

    /// A world-space point and unit direction in this shape's own frame.
    #[inline]
    fn to_local(&self, point: Vec3, dir: Vec3) -> (Vec3, Vec3) {
        (
            self.pose.inverse_transform_point(point),
            self.pose.rotation.inverse() * dir,
        )
    }

    /// A closed-form answer in this shape's frame as a world-space hit; `None` for an
    /// overlap at the start.
    fn found(&self, sweep: BallSweep) -> Option<Option<SweepHit>> {
        match sweep {
            BallSweep::Miss => Some(None),
            BallSweep::Hit { distance, normal } => Some(Some(SweepHit {
                distance,
                normal: self.pose.rotation * normal,
            })),
            BallSweep::Overlap => None,
        }
    }
}

/// A heightfield mesh's grid of cells in its own frame (the triangles of cell `(i, j)` are
/// `2·(j·nx + i)` and the one after, as [`ShapeDesc::collision_shapes`] builds them).
/// Traces find the triangles under them by cell, which for the short sweeps of a
/// locomotion graph is a few cells, instead of walking the mesh's tree.
#[derive(Clone, Copy, Debug)]
struct Grid {
    /// Corner of cell (0, 0), x and y (cm).
    origin: (f32, f32),
    /// Size of the whole grid, x and y (cm).
    size: (f32, f32),
    /// Cells along x and y (each ≥ 1).
    cells: (u32, u32),
}

/// A rectangle of a [`Grid`]'s cells, inclusive.
#[derive(Clone, Copy, Debug)]
struct CellRange {
    /// Cells along x in the whole grid.
    nx: u32,
    i: (u32, u32),
    j: (u32, u32),
}

/// The most cells a trace reads by cell; a longer sweep asks the mesh's tree, which
/// narrows a long diagonal better than its bounding rectangle of cells.
const MAX_GRID_CELLS: u32 = 64;

impl Grid {
    /// The grid of a heightfield description; `None` for other shapes.
    fn of(desc: &ShapeDesc) -> Option<Grid> {
        match *desc {
            ShapeDesc::Heightfield {
                origin,
                size,
                cells,
                ..
            } => Some(Grid {
                origin: (origin.0, origin.1),
                size,
                cells: (cells.0.max(1), cells.1.max(1)),
            }),
            _ => None,
        }
    }

    /// `desc`'s built collision shapes, each with the grid of the heightfield it came from.
    fn attach(
        desc: &ShapeDesc,
        built: Vec<(Pose, SharedShape)>,
    ) -> impl Iterator<Item = (Pose, SharedShape, Option<Grid>)> {
        let grid = Grid::of(desc);
        built
            .into_iter()
            .map(move |(pose, shape)| (pose, shape, grid))
    }

    /// The cells whose rectangle (grown by [`CULL_MARGIN`] against rounding) meets
    /// `reach`'s, clamped to the grid; an empty range when it lies outside. `None` when
    /// that is more than [`MAX_GRID_CELLS`] (or not finite).
    fn cells_under(&self, reach: &Aabb) -> Option<CellRange> {
        let axis = |lo: f32, hi: f32, origin: f32, size: f32, n: u32| -> Option<(u32, u32)> {
            let scale = n as f32 / size;
            let (a, b) = (
                (lo - CULL_MARGIN - origin) * scale,
                (hi + CULL_MARGIN - origin) * scale,
            );
            if !(a.is_finite() && b.is_finite()) {
                return None;
            }
            let (a, b) = (cell_floor(a), cell_floor(b));
            if b < 0.0 || a >= n as f32 {
                // Outside the grid: no cells (an empty range).
                return Some((1, 0));
            }
            Some((a.max(0.0) as u32, (b as u32).min(n - 1)))
        };
        let (cx, cy) = self.cells;
        let i = axis(reach.mins.x, reach.maxs.x, self.origin.0, self.size.0, cx)?;
        let j = axis(reach.mins.y, reach.maxs.y, self.origin.1, self.size.1, cy)?;
        let count = |(a, b): (u32, u32)| (b + 1).saturating_sub(a);
        (count(i).saturating_mul(count(j)) <= MAX_GRID_CELLS).then_some(CellRange { nx: cx, i, j })
    }
}

/// `x.floor()` for a finite `x` as far as a grid's cell numbers go: exact below 2³¹ in
/// size, and past that ±2³¹, which lies outside every grid as the true floor does. Written
/// out because `f32::floor` is a call into the C library on the baseline x86-64 (a cell
/// lookup takes four).
#[inline]
fn cell_floor(x: f32) -> f32 {
    // `as` saturates at the ends of `i32`, and truncates towards zero.
    let t = x as i32 as f32;
    if t > x { t - 1.0 } else { t }
}

impl CellRange {
    /// The triangles of the range's cells, row by row.
    fn triangles(self) -> CellTriangles {
        let Self { nx, i, j } = self;
        if i.0 > i.1 || j.0 > j.1 {
            // No cells: no numbers.
            return CellTriangles {
                next: 0,
                row_end: 0,
                rows_left: 0,
                skip: 0,
                width: 0,
            };
        }
        // A row's cells' triangles are numbered one after another.
        let first = 2 * (j.0 * nx + i.0);
        let width = 2 * (i.1 + 1 - i.0);
        CellTriangles {
            next: first,
            row_end: first + width,
            rows_left: j.1 - j.0,
            skip: 2 * nx - width,
            width,
        }
    }
}

/// The triangle numbers of a [`CellRange`], row by row: in each row, its cells' triangles,
/// numbered one after another. Written out rather than as nested ranges, whose iterator
/// costs several times the few instructions a triangle needs here.
#[derive(Clone, Copy, Debug)]
struct CellTriangles {
    /// The next number in the current row.
    next: u32,
    /// One past the current row's last number.
    row_end: u32,
    /// Rows after the current one.
    rows_left: u32,
    /// Numbers between one row's end and the next row's start.
    skip: u32,
    /// Numbers in a row.
    width: u32,
}

impl Iterator for CellTriangles {
    type Item = u32;

    #[inline]
    fn next(&mut self) -> Option<u32> {
        if self.next == self.row_end {
            if self.rows_left == 0 {
                return None;
            }
            self.rows_left -= 1;
            self.next += self.skip;
            self.row_end = self.next + self.width;
        }
        let k = self.next;
        self.next += 1;
        Some(k)
    }
}

/// The closed-form description of a convex hull from its surface triangles (its own frame):
/// each triangle's plane, turned to face away from the hull's centre.
fn hull_form((vertices, indices): (Vec<Vec3>, Vec<[u32; 3]>)) -> Form {
    let (triangles, planes) = hull_facets(&vertices, &indices);
    Form::Hull {
        triangles: triangles.into(),
        planes: planes.into(),
    }
}

/// How much (cm) bounding boxes are widened before a trace skips a shape: far more than
/// parry3d's query tolerances, so a skipped shape is one the exact query would have missed
/// and answers are the same with or without the boxes.
const CULL_MARGIN: f32 = 0.01;

impl fmt::Debug for World {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("World")
            .field("desc", &self.desc)
            .field("collision_shapes", &self.colliders.len())
            .finish()
    }
}

impl Default for World {
    /// An empty world: every trace misses.
    fn default() -> Self {
        Self::with_shapes(WorldDesc::default(), Vec::new())
    }
}

fn pose(translation: Vec3, yaw_deg: f32) -> Pose {
    Pose::from_parts(translation, Quat::from_rotation_z(yaw_deg.to_radians()))
}

fn v3(t: (f32, f32, f32)) -> Vec3 {
    Vec3::new(t.0, t.1, t.2)
}

/// The generated height (above `origin.z`, before explicit heights) of a heightfield's waves
/// at world XY `(x, y)`, centimetres.
#[must_use]
pub fn wave_height(waves: &[Wave], origin: (f32, f32), x: f32, y: f32) -> f32 {
    let mut h = 0.0;
    for w in waves {
        let d = yaw_direction(w.heading);
        let along = d.x * (x - origin.0) + d.y * (y - origin.1);
        h += w.amplitude
            * (core::f32::consts::TAU * along / w.wavelength + w.phase.to_radians()).sin();
    }
    h
}

impl World {
    /// Builds a world, checking every shape.
    pub fn try_from_desc(desc: &WorldDesc) -> Result<World, WorldError> {
        let mut shapes = Vec::new();
        for (index, shape) in desc.shapes.iter().enumerate() {
            shape
                .validate()
                .map_err(|message| WorldError::InvalidShape {
                    index,
                    kind: shape.kind(),
                    message,
                })?;
            let built = shape
                .collision_shapes()
                .map_err(|message| WorldError::Geometry {
                    index,
                    kind: shape.kind(),
                    message,
                })?;
            shapes.extend(Grid::attach(shape, built));
        }
        Ok(World::with_shapes(desc.clone(), shapes))
    }

    /// A world of built shapes and the description they came from.
    fn with_shapes(desc: WorldDesc, shapes: Vec<(Pose, SharedShape, Option<Grid>)>) -> World {
        // Each collider with its world-space bounding box, loosened by `CULL_MARGIN`;
        // `None` for a half-space (unbounded), which every trace tests on its own.
        let built = shapes
            .into_iter()
            .map(|(pose, shape, grid)| {
                let form = if let Some(h) = shape.as_halfspace() {
                    let normal = (pose.rotation * h.normal).normalize_or_zero();
                    if normal == Vec3::ZERO {
                        Form::Other
                    } else {
                        Form::HalfSpace {
                            point: pose.translation,
                            normal,
                        }
                    }
                } else if let Some(cuboid) = shape.as_cuboid() {
                    Form::Box {
                        half: cuboid.half_extents,
                    }
                } else if let Some(mesh) = shape.as_trimesh() {
                    let normals = (0..mesh.num_triangles() as u32)
                        .map(|i| {
                            let t = mesh.triangle(i);
                            Facet::normal_of([t.a, t.b, t.c])
                        })
                        .collect();
                    Form::Mesh { grid, normals }
                } else if let Some(hull) = shape.as_convex_polyhedron() {
                    hull_form(hull.to_trimesh())
                } else {
                    Form::Other
                };
                let bounds = (!matches!(form, Form::HalfSpace { .. }))
                    .then(|| shape.compute_aabb(&pose).loosened(CULL_MARGIN));
                (Collider { pose, shape, form }, bounds)
            })
            .collect::<Vec<_>>();
        let (colliders, bounds): (Vec<Collider>, Vec<Option<Aabb>>) = built.into_iter().unzip();
        let quads: Vec<Quad> = bounds
            .chunks(4)
            .map(|four| {
                let mut lo = [[f32::INFINITY; 4]; 3];
                let mut hi = [[f32::NEG_INFINITY; 4]; 3];
                for (k, b) in four.iter().enumerate() {
                    if let Some(b) = b {
                        for axis in 0..3 {
                            lo[axis][k] = b.mins[axis];
                            hi[axis][k] = b.maxs[axis];
                        }
                    }
                }
                Quad {
                    lo: lo.map(Vec4::from_array),
                    hi: hi.map(Vec4::from_array),
                }
            })
            .collect();
        let half_spaces = (colliders.iter().enumerate())
            .filter_map(|(index, c)| match c.form {
                Form::HalfSpace { point, normal } => Some(HalfSpace {
                    point,
                    normal,
                    index,
                }),
                _ => None,
            })
            .collect();
        World {
            desc,
            colliders,
            bounded: bounds.iter().any(Option::is_some),
            quads,
            half_spaces,
        }
    }

    /// The bounded colliders whose bounds meet `reach`, in order.
    #[inline(always)]
    fn near(&self, reach: Aabb) -> Near<'_> {
        Near {
            world: self,
            reach,
            quad: 0,
            bits: 0,
        }
    }

    /// Builds a world, leaving out any shape that [`ShapeDesc::validate`] rejects or that
    /// parry3d cannot build (use [`World::try_from_desc`] to get those errors instead).
    /// Descriptions read by [`World::load`], [`World::from_str`] or a scenario file are
    /// already checked.
    #[must_use]
    pub fn from_desc(desc: &WorldDesc) -> World {
        let mut shapes = Vec::new();
        let mut kept = Vec::new();
        for shape in &desc.shapes {
            if shape.validate().is_ok()
                && let Ok(built) = shape.collision_shapes()
            {
                shapes.extend(Grid::attach(shape, built));
                kept.push(shape.clone());
            }
        }
        World::with_shapes(WorldDesc { shapes: kept }, shapes)
    }

    /// Reads a world description file (RON, see the module docs) and builds it.
    pub fn load(path: impl AsRef<Path>) -> Result<World, WorldError> {
        let path = path.as_ref();
        let text = std::fs::read_to_string(path).map_err(|source| WorldError::Io {
            path: path.to_path_buf(),
            source,
        })?;
        Self::parse(&text, &path.display().to_string())
    }

    /// Parses a world description from RON text and builds it. Errors name `<string>`.
    #[allow(clippy::should_implement_trait)]
    pub fn from_str(text: &str) -> Result<World, WorldError> {
        Self::parse(text, "<string>")
    }

    /// Parses RON text; `origin` names the text in error messages.
    fn parse(text: &str, origin: &str) -> Result<World, WorldError> {
        let desc: WorldDesc = ron_options().from_str(text).map_err(|e| {
            let (message, help) = describe_ron_error(&e.code);
            WorldError::Parse {
                origin: origin.to_string(),
                line: e.span.start.line,
                col: e.span.start.col,
                message,
                help,
            }
        })?;
        Self::try_from_desc(&desc)
    }

    /// The description the world was built from (without shapes [`World::from_desc`] left
    /// out).
    #[must_use]
    pub fn desc(&self) -> &WorldDesc {
        &self.desc
    }

    /// The first surface straight below `(x, y, from_z)` (world space, centimetres), looking
    /// down at most [`GROUND_SEARCH_DEPTH`]: its height and its unit normal (away from the
    /// surface). `None` over the void. A start point inside a solid shape gives
    /// `(from_z, +Z)`.
    #[must_use]
    pub fn ground_height(&self, x: f32, y: f32, from_z: f32) -> Option<(f32, Vec3)> {
        let start = Vec3::new(x, y, from_z);
        let hit = self.line_trace(start, start - Vec3::Z * GROUND_SEARCH_DEPTH)?;
        Some((hit.point.z, hit.normal))
    }

    /// Sweeps `shape` (at `start`, not rotated) by `delta`; the nearest hit within the
    /// sweep, keeping `skin` centimetres from surfaces. A sweep that starts within `skin` of
    /// a surface and moves away from it does not hit it.
    pub(crate) fn sweep(
        &self,
        shape: &dyn Shape,
        start: Vec3,
        delta: Vec3,
        skin: f32,
        stop_at_penetration: bool,
    ) -> Option<SweepHit> {
        let length = delta.length();
        if !(length.is_finite() && start.is_finite()) || length <= 1e-7 {
            return None;
        }
        let ball_radius = if skin == 0.0 {
            shape.as_ball().map(|ball| ball.radius)
        } else {
            None
        };
        let along = Along {
            delta,
            dir: delta / length,
            length,
        };
        self.sweep_along(shape, ball_radius, start, along, skin, stop_at_penetration)
    }

    /// [`World::sweep`] with its delta's direction and length known (`along`), and
    /// `ball_radius` the radius when `shape` is a ball swept without skin (which the
    /// closed forms answer). Sphere traces that move take [`World::ball_trace`] instead.
    #[inline(always)]
    fn sweep_along(
        &self,
        shape: &dyn Shape,
        ball_radius: Option<f32>,
        start: Vec3,
        along: Along,
        skin: f32,
        stop_at_penetration: bool,
    ) -> Option<SweepHit> {
        let Along { delta, dir, length } = along;
        // The half-spaces first, then the bounded colliders near the sweep.
        let half_spaces =
            (self.half_spaces.iter()).filter_map(|h| Some((h.index, self.colliders.get(h.index)?)));
        let bounded = self.bounded.then(|| {
            let end = start + delta;
            let reach = if let Some(radius) = ball_radius {
                ball_reach(start, end, radius)
            } else {
                let local = shape.compute_local_aabb();
                Aabb::new(start + local.mins, start + local.maxs)
                    .merged(&Aabb::new(end + local.mins, end + local.maxs))
                    .loosened(skin.max(0.0))
            };
            self.near(reach)
        });
        // The nearest hit so far and its collider's index: of equal distances the collider
        // listed first wins, as when every collider is tested in order.
        let mut best: Option<(SweepHit, usize)> = None;
        for (k, collider) in half_spaces.chain(bounded.into_iter().flatten()) {
            let closed_form = ball_radius
                .and_then(|r| collider.ball_sweep(start, dir, length, r, stop_at_penetration));
            let found = match closed_form {
                Some(found) => found,
                None => collider.cast(shape, start, along, skin, stop_at_penetration),
            };
            if let Some(hit) = found
                && best.is_none_or(|(b, bk)| {
                    hit.distance < b.distance || (hit.distance == b.distance && k < bk)
                })
            {
                best = Some((hit, k));
            }
        }
        best.map(|(hit, _)| hit)
    }

    /// The bounded colliders' part of a line trace from `ray`'s origin to `end` (`length`
    /// apart): each near the segment offered to `best` (distance, normal and collider
    /// index), which wins ties by the lower index.
    #[inline]
    fn ray_bounded(
        &self,
        ray: &Ray,
        end: Vec3,
        length: f32,
        best: &mut Option<(f32, Vec3, usize)>,
    ) {
        let reach = Aabb::new(ray.origin.min(end), ray.origin.max(end));
        for (k, collider) in self.near(reach) {
            if let Some((d, normal)) = collider.ray(ray, length)
                && best.is_none_or(|(b, _, bk)| d < b || (d == b && k < bk))
            {
                *best = Some((d, normal, k));
            }
        }
    }

    /// A sphere trace's sweep ([`World::sweep_along`] of `ball`, stopping at penetration):
    /// the half-spaces first, each in closed form, then the bounded colliders near the
    /// sweep. Of equal distances the collider listed first wins, as when every collider is
    /// tested in order.
    #[inline(always)]
    fn ball_trace(&self, ball: &Ball, start: Vec3, along: Along) -> Option<SweepHit> {
        let (dir, length, radius) = (along.dir, along.length, ball.radius);
        let mut best: Option<(SweepHit, usize)> = None;
        for h in &self.half_spaces {
            if let Some(distance) =
                ball_half_space_sweep(start, dir, length, radius, h.point, h.normal, true)
                && best.is_none_or(|(b, _)| distance < b.distance)
            {
                let hit = SweepHit {
                    distance,
                    normal: h.normal,
                };
                best = Some((hit, h.index));
            }
        }
        if self.bounded {
            self.ball_trace_bounded(ball, start, along, &mut best);
        }
        best.map(|(hit, _)| hit)
    }

    /// The bounded colliders' part of [`World::ball_trace`]: each near the sweep offered
    /// to `best` (a hit and its collider's index), which wins ties by the lower index.
    #[inline]
    fn ball_trace_bounded(
        &self,
        ball: &Ball,
        start: Vec3,
        along: Along,
        best: &mut Option<(SweepHit, usize)>,
    ) {
        let (dir, length, radius) = (along.dir, along.length, ball.radius);
        let reach = ball_reach(start, start + along.delta, radius);
        for (k, collider) in self.near(reach) {
            let found = match collider.ball_sweep_bounded(start, dir, length, radius) {
                Some(found) => found,
                None => collider.cast(ball, start, along, 0.0, true),
            };
            if let Some(hit) = found
                && best.is_none_or(|(b, bk)| {
                    hit.distance < b.distance || (hit.distance == b.distance && k < bk)
                })
            {
                *best = Some((hit, k));
            }
        }
    }
}

/// Where a ray (`length` long) meets the half-space through `point` with unit outward
/// `normal`: the distance and the normal, `(0, 0)` for a ray starting inside, `None` for a
/// miss.
#[inline(always)]
fn ray_half_space(ray: &Ray, length: f32, point: Vec3, normal: Vec3) -> Option<(f32, Vec3)> {
    // Height of the start above the plane; below it, the ray starts inside.
    let height = normal.dot(ray.origin - point);
    if height < 0.0 {
        return Some((0.0, Vec3::ZERO));
    }
    let t = height / -normal.dot(ray.dir);
    (t >= 0.0 && t <= length).then_some((t, normal))
}

/// A line trace's answer from the nearest hit of its segment (from `start`, along the unit
/// `dir`): the distance travelled (below 0 counts as 0) and the surface's normal (zero
/// for a segment starting inside), made unit ([`unit_normal`]), then as [`facing_hit`].
#[inline(always)]
fn line_hit(start: Vec3, dir: Vec3, distance: f32, normal: Vec3) -> TraceHit {
    facing_hit(start, dir, distance, unit_normal(normal))
}

/// A hit's normal made unit: zero where it is zero or not finite.
#[inline(always)]
fn unit_normal(normal: Vec3) -> Vec3 {
    if normal.is_finite() {
        normal.normalize_or_zero()
    } else {
        Vec3::ZERO
    }
}

/// [`line_hit`] with the normal already made unit (`unit`: zero where the shape gave none
/// or it was not finite; see [`unit_normal`]): the normal is made to face the segment,
/// `−dir` where there is none or the segment starts inside (at distance 0), turned over
/// where it was hit from behind. [`World::plane_line_traces`] makes its plane's normal
/// unit once for a batch.
#[inline(always)]
fn facing_hit(start: Vec3, dir: Vec3, distance: f32, unit: Vec3) -> TraceHit {
    let distance = distance.max(0.0);
    let mut normal = if distance > 0.0 { unit } else { Vec3::ZERO };
    if normal == Vec3::ZERO {
        normal = -dir;
    } else if normal.dot(dir) > 0.0 {
        // A surface (the heightfield) hit from behind: the normal faces the ray.
        normal = -normal;
    }
    TraceHit {
        point: start + dir * distance,
        normal,
        distance,
    }
}

/// The options every RON file of the host is read with (`Some(...)` may be left out).
pub(crate) fn ron_options() -> ron::Options {
    ron::Options::default().with_default_extension(ron::extensions::Extensions::IMPLICIT_SOME)
}

/// A message and a "how to fix it" hint for a RON error.
pub(crate) fn describe_ron_error(code: &ron::Error) -> (String, String) {
    use ron::Error as E;
    let message = code.to_string();
    let help = match code {
        E::MissingStructField { field, .. } => format!("add the field `{field}: ...`"),
        E::NoSuchStructField { .. } => {
            "remove or rename the field (the expected names are listed above)".to_string()
        }
        E::NoSuchEnumVariant { .. } => {
            "use one of the listed names (they are case-sensitive)".to_string()
        }
        E::DuplicateStructField { field, .. } => format!("write `{field}` only once"),
        E::Message(_) => "fix the value named above".to_string(),
        E::ExpectedFloat | E::ExpectedInteger => {
            "write a number here (floats need a digit after the point, e.g. `1.0`)".to_string()
        }
        E::TrailingCharacters => {
            "remove what follows the closing parenthesis of the top-level value".to_string()
        }
        _ => {
            "check brackets, commas and the field names against the format in the docs".to_string()
        }
    };
    (message, help)
}

impl WorldQuery for World {
    /// First hit of the segment `start → end` (world space, centimetres). Shapes are solid:
    /// a segment starting inside one hits at distance 0 with the normal `−direction`. A
    /// zero-length or non-finite segment misses.
    fn line_trace(&self, start: Vec3, end: Vec3) -> Option<TraceHit> {
        self.line_trace_inlined(start, end)
    }

    /// First hit of a sphere of `radius` centimetres swept from `start` to `end` (world
    /// space). `distance` is how far the centre travelled, `point` the touched surface
    /// point. A sphere overlapping geometry at the start hits at distance 0. A radius of 0
    /// is a line trace; a negative or non-finite radius, or non-finite ends, miss. A
    /// zero-length sweep reports an overlap at the start, if any.
    fn sphere_trace(&self, start: Vec3, end: Vec3, radius: f32) -> Option<TraceHit> {
        self.sphere_trace_inlined(start, end, radius)
    }

    /// Each query as [`World::line_trace`] answers it, bit for bit. In a world of one
    /// half-space and nothing else (flat ground), [`TRACE_COLUMNS`] queries at a time, one
    /// array per coordinate, as [`WorldQuery::line_traces_in_columns`]; otherwise one at
    /// a time.
    fn line_traces(&self, queries: &[LineQuery], hits: &mut [Option<TraceHit>]) {
        self.answer_batch(
            queries,
            hits,
            |traces, k, q| traces.set_line(k, *q),
            |plane, traces, n, answers| self.plane_line_traces(plane, traces, n, answers),
            |q| self.line_trace_inlined(q.start, q.end),
        );
    }

    /// Each query as [`World::sphere_trace`] answers it, bit for bit. In a world of one
    /// half-space and nothing else (flat ground), [`TRACE_COLUMNS`] queries at a time, one
    /// array per coordinate, so that the compiler can compute several queries per
    /// instruction; otherwise one at a time.
    fn sphere_traces(&self, queries: &[SphereQuery], hits: &mut [Option<TraceHit>]) {
        self.answer_batch(
            queries,
            hits,
            |traces, k, q| traces.set_sphere(k, *q),
            |plane, traces, n, answers| self.plane_sphere_traces(plane, traces, n, answers),
            |q| self.sphere_trace_inlined(q.start, q.end, q.radius),
        );
    }

    /// Each trace as [`World::line_trace`] answers it, bit for bit: in a world of one
    /// half-space and nothing else (flat ground) all at once, in their columns; otherwise
    /// one at a time.
    fn line_traces_in_columns(&self, traces: &TraceColumns, n: usize, hits: &mut HitColumns) {
        let n = n.min(TRACE_COLUMNS);
        match self.flat_ground() {
            Some(plane) => self.plane_line_traces(plane, traces, n, hits),
            None => {
                for k in 0..n {
                    let q = traces.line(k);
                    hits.set(k, self.line_trace_inlined(q.start, q.end));
                }
            }
        }
    }

    /// Each trace as [`World::sphere_trace`] answers it, bit for bit, as
    /// [`World::line_traces_in_columns`].
    fn sphere_traces_in_columns(&self, traces: &TraceColumns, n: usize, hits: &mut HitColumns) {
        let n = n.min(TRACE_COLUMNS);
        match self.flat_ground() {
            Some(plane) => self.plane_sphere_traces(plane, traces, n, hits),
            None => {
                for k in 0..n {
                    let q = traces.sphere(k);
                    hits.set(k, self.sphere_trace_inlined(q.start, q.end, q.radius));
                }
            }
        }
    }
}

impl World {
    /// The world's only collider when it is one half-space and nothing else (flat
    /// ground), whose traces are answered in columns.
    #[inline(always)]
    fn flat_ground(&self) -> Option<&HalfSpace> {
        match (self.bounded, &self.half_spaces[..]) {
            (false, [plane]) => Some(plane),
            _ => None,
        }
    }

    /// A batch's answers, `hits[k]` to `queries[k]`: in a world of one half-space and
    /// nothing else (flat ground), [`TRACE_COLUMNS`] queries at a time, each `put` into
    /// its column and the columns answered by `columns`; otherwise one at a time by
    /// `alone`.
    #[inline(always)]
    fn answer_batch<Q>(
        &self,
        queries: &[Q],
        hits: &mut [Option<TraceHit>],
        put: impl Fn(&mut TraceColumns, usize, &Q),
        columns: impl Fn(&HalfSpace, &TraceColumns, usize, &mut HitColumns),
        alone: impl Fn(&Q) -> Option<TraceHit>,
    ) {
        match self.flat_ground() {
            Some(plane) => {
                for (queries, hits) in queries
                    .chunks(TRACE_COLUMNS)
                    .zip(hits.chunks_mut(TRACE_COLUMNS))
                {
                    // Lanes past the queries stay zero.
                    let mut traces = TraceColumns::default();
                    for (k, q) in queries.iter().enumerate() {
                        put(&mut traces, k, q);
                    }
                    let mut answers = HitColumns::default();
                    let n = queries.len().min(hits.len());
                    columns(plane, &traces, n, &mut answers);
                    for (k, hit) in hits.iter_mut().enumerate().take(n) {
                        *hit = answers.get(k);
                    }
                }
            }
            None => {
                for (query, hit) in queries.iter().zip(hits) {
                    *hit = alone(query);
                }
            }
        }
    }

    /// [`WorldQuery::line_trace`], inlined where it is called: once for that method and
    /// once in the loop of [`WorldQuery::line_traces`]. [`World::plane_line_traces`]
    /// computes the same for a flat world in columns and must be kept in step with it.
    #[inline(always)]
    fn line_trace_inlined(&self, start: Vec3, end: Vec3) -> Option<TraceHit> {
        // Read as the caller stored them (see `load_vec3`).
        let (start, end) = (Vec3::from(load_vec3(&start)), Vec3::from(load_vec3(&end)));
        let delta = end - start;
        let length = delta.length();
        if !(start.is_finite() && end.is_finite() && length.is_finite()) || length <= 1e-7 {
            return None;
        }
        let dir = delta / length;
        let ray = Ray::new(start, dir);
        // The half-spaces first, in closed form, then the bounded colliders near the
        // segment; of equal distances the collider listed first wins.
        let mut best: Option<(f32, Vec3, usize)> = None;
        for h in &self.half_spaces {
            if let Some((d, normal)) = ray_half_space(&ray, length, h.point, h.normal)
                && best.is_none_or(|(b, _, _)| d < b)
            {
                best = Some((d, normal, h.index));
            }
        }
        if self.bounded {
            self.ray_bounded(&ray, end, length, &mut best);
        }
        let (distance, normal, _) = best?;
        Some(line_hit(start, dir, distance, normal))
    }

    /// [`WorldQuery::sphere_trace`], inlined where it is called: once for that method and
    /// once in the loop of [`WorldQuery::sphere_traces`]. [`World::plane_sphere_traces`]
    /// computes the same for a flat world in columns and must be kept in step with it.
    #[inline(always)]
    fn sphere_trace_inlined(&self, start: Vec3, end: Vec3, radius: f32) -> Option<TraceHit> {
        // Read as the caller stored them (see `load_vec3`).
        let (a, b) = (load_vec3(&start), load_vec3(&end));
        if !(all_finite([a, b, Vec3A::splat(radius)]) && radius >= 0.0) {
            return None;
        }
        if radius == 0.0 {
            return self.line_trace(start, end);
        }
        let ball = Ball::new(radius);
        // In SIMD registers (the same operations, lane by lane, as on three floats).
        let delta = b - a;
        let length = delta.length();
        let (dir, hit) = if length <= 1e-7 {
            // Overlap test: a tiny sweep that any overlap stops at distance 0.
            let hit = self
                .sweep(&ball, start, Vec3::NEG_Z * 1e-6, 0.0, true)
                .filter(|h| h.distance <= 0.0)?;
            (Vec3A::ZERO, hit)
        } else if length.is_finite() {
            // `sweep` without asking the shape again what it is.
            let dir = delta / length;
            let along = Along {
                delta: delta.into(),
                dir: dir.into(),
                length,
            };
            let hit = self.ball_trace(&ball, start, along)?;
            (dir, hit)
        } else {
            return None;
        };
        // The touched point of a sphere is one radius from its centre, against the normal.
        let point = a + dir * hit.distance - Vec3A::from(hit.normal) * radius;
        Some(TraceHit {
            point: point.into(),
            normal: hit.normal,
            distance: hit.distance,
        })
    }

    /// The first `n` line traces of `traces` against the world's only collider, the
    /// half-space `plane`, answered into `hits`: what [`WorldQuery::line_trace`] computes
    /// for each, with the same operations in the same order (so bit for bit the same
    /// answers), in the columns the traces come in, every column at once and without
    /// branches, so that the compiler computes several traces per instruction. A trace
    /// off the common path (not finite, a length of 1e-7 or less or not finite) is
    /// answered by `line_trace` itself. Kept in step with [`World::line_trace_inlined`],
    /// [`ray_half_space`] and [`facing_hit`]: a change to any of them must be made here too
    /// (`line_traces_in_a_batch_answer_as_each_alone` compares them).
    fn plane_line_traces(
        &self,
        plane: &HalfSpace,
        traces: &TraceColumns,
        n: usize,
        hits: &mut HitColumns,
    ) {
        let (p, nrm) = (plane.point.to_array(), plane.normal.to_array());
        // `line_hit`'s unit normal, the same for every hit but those starting inside (whose
        // normal is zero).
        let unit = unit_normal(plane.normal).to_array();
        let no_unit = unit == [0.0; 3];
        let [sx, sy, sz] = &traces.start;
        let [ex, ey, ez] = &traces.end;
        let mut common = [false; TRACE_COLUMNS];
        for k in 0..TRACE_COLUMNS {
            let (dx, dy, dz) = (ex[k] - sx[k], ey[k] - sy[k], ez[k] - sz[k]);
            // `Vec3::length`: (x² + y²) + z², then the square root.
            let length = ((dx * dx + dy * dy) + dz * dz).sqrt();
            let dir = [dx / length, dy / length, dz / length];
            // `ray_half_space`: the start's height above the plane, below which the ray
            // starts inside; else where it crosses.
            let height =
                (nrm[0] * (sx[k] - p[0]) + nrm[1] * (sy[k] - p[1])) + nrm[2] * (sz[k] - p[2]);
            let t = height / -((nrm[0] * dir[0] + nrm[1] * dir[1]) + nrm[2] * dir[2]);
            let inside = height < 0.0;
            // Without short-circuits, so that the loop has no branches to keep it from
            // computing several lanes at once (a NaN `t` misses, as there).
            hits.hit[k] = inside | ((t >= 0.0) & (t <= length));
            // `facing_hit`, lane by lane: the distance at least 0; the normal the unit one
            // for a hit on the way, turned over where it is hit from behind, and for a hit
            // at the start (or where the plane gave no normal) one facing back along the
            // ray.
            let distance = (if inside { 0.0 } else { t }).max(0.0);
            let facing = !inside & (distance > 0.0) & !no_unit;
            let behind = ((unit[0] * dir[0] + unit[1] * dir[1]) + unit[2] * dir[2]) > 0.0;
            // Chosen bit by bit (a negation is the sign bit's flip), which the compiler
            // computes for several lanes at once where it would not pick among floats.
            let (turn, pick) = (
                u32::from(behind) << 31,
                0u32.wrapping_sub(u32::from(facing)),
            );
            let start = [sx[k], sy[k], sz[k]];
            for c in 0..3 {
                let towards = unit[c].to_bits() ^ turn;
                let back = (-dir[c]).to_bits();
                hits.normal[c][k] = f32::from_bits((towards & pick) | (back & !pick));
                hits.point[c][k] = start[c] + dir[c] * distance;
            }
            hits.distance[k] = distance;
            // `line_trace`'s own tests: a finite start and a finite length above 1e-7 (so
            // a finite end).
            common[k] = all_finite([sx[k], sy[k], sz[k], length]) & (length > 1e-7);
        }
        for k in (0..n).filter(|&k| !common[k]) {
            let q = traces.line(k);
            hits.set(k, self.line_trace(q.start, q.end));
        }
    }

    /// The first `n` sphere traces of `traces` against the world's only collider, the
    /// half-space `plane`, answered into `hits`: what [`WorldQuery::sphere_trace`]
    /// computes for each, with the same operations in the same order (so bit for bit the
    /// same answers), in the columns the traces come in, every column at once and without
    /// branches, so that the compiler computes several traces per instruction. A trace
    /// off the common path (not finite, a radius of 0 or less, a length of 1e-7 or less
    /// or not finite) is answered by `sphere_trace` itself. Kept in step with
    /// [`World::sphere_trace_inlined`] and [`ball_half_space_sweep`]: a change to either
    /// must be made here too (`sphere_traces_in_a_batch_answer_as_each_alone` compares
    /// them).
    fn plane_sphere_traces(
        &self,
        plane: &HalfSpace,
        traces: &TraceColumns,
        n: usize,
        hits: &mut HitColumns,
    ) {
        let (p, nrm) = (plane.point.to_array(), plane.normal.to_array());
        let [sx, sy, sz] = &traces.start;
        let [ex, ey, ez] = &traces.end;
        let radius = &traces.radius;
        let mut common = [false; TRACE_COLUMNS];
        for k in 0..TRACE_COLUMNS {
            let (dx, dy, dz) = (ex[k] - sx[k], ey[k] - sy[k], ez[k] - sz[k]);
            // `Vec3A::length`: (x² + y²) + z², then the square root.
            let length = ((dx * dx + dy * dy) + dz * dz).sqrt();
            let dir = [dx / length, dy / length, dz / length];
            // `ball_half_space_sweep`, stopping at penetration.
            let gap = ((nrm[0] * (sx[k] - p[0]) + nrm[1] * (sy[k] - p[1]))
                + nrm[2] * (sz[k] - p[2]))
                - radius[k];
            let approach = -((nrm[0] * dir[0] + nrm[1] * dir[1]) + nrm[2] * dir[2]);
            let along = gap / approach;
            let touching = gap <= 0.0;
            // Without short-circuits, so that the loop has no branches to keep it from
            // computing several lanes at once. (`ball_half_space_sweep` returns a miss for
            // `approach <= 0`; a NaN approach misses here too, its `along` being NaN.)
            hits.hit[k] = touching | ((approach > 0.0) & (along <= length));
            let distance = if touching { 0.0 } else { along };
            // The touched point of a sphere is one radius from its centre, against the
            // normal: `(start + dir · distance) − normal · radius`, as `sphere_trace`.
            let start = [sx[k], sy[k], sz[k]];
            for c in 0..3 {
                hits.point[c][k] = (start[c] + dir[c] * distance) - nrm[c] * radius[k];
                hits.normal[c][k] = nrm[c];
            }
            hits.distance[k] = distance;
            // `sphere_trace`'s own tests: a finite start and radius, a radius above 0, and a
            // finite length above 1e-7 (so a finite end).
            common[k] = all_finite([sx[k], sy[k], sz[k], radius[k], length])
                & (radius[k] > 0.0)
                & (length > 1e-7);
        }
        for k in (0..n).filter(|&k| !common[k]) {
            let q = traces.sphere(k);
            hits.set(k, self.sphere_trace(q.start, q.end, q.radius));
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::signed;
    use parry3d::shape::Capsule;

    #[test]
    fn a_range_of_cells_lists_their_triangles_row_by_row() {
        // Against the rule written out: for each row, for each cell, its two triangles
        // 2·(row·nx + col) and the one after; on a grid 7 cells wide, every range of
        // cells in it, a single cell, a whole row and column, and the empty range.
        let nx = 7;
        for (i, j) in [
            ((0, 6), (0, 4)),
            ((2, 2), (3, 3)),
            ((0, 6), (2, 2)),
            ((3, 3), (0, 4)),
            ((1, 0), (0, 4)),
            ((0, 6), (1, 0)),
            ((4, 5), (1, 3)),
        ] {
            let expected: Vec<u32> = (j.0..=j.1)
                .flat_map(|row| {
                    (i.0..=i.1)
                        .flat_map(move |col| [2 * (row * nx + col), 2 * (row * nx + col) + 1])
                })
                .collect();
            let listed: Vec<u32> = CellRange { nx, i, j }.triangles().collect();
            assert_eq!(listed, expected, "cells {i:?} × {j:?}");
        }
    }

    #[test]
    fn cell_floor_is_floor_over_every_grid() {
        // Against the C library's floor: whole numbers and their neighbours one step of
        // f32 either side, both signs, zeros, fractions, numbers up to 1e9 in size (where
        // f32 holds only whole numbers) and the last ones below 2³¹; past that, ±2³¹
        // (outside every grid).
        let edge = 2f32.powi(31);
        let mut values = vec![0.0_f32, -0.0, 0.5, -0.5, 0.999_999_94, -0.999_999_94];
        values.extend([edge - 128.0, -(edge - 128.0), -edge, edge.next_down()]);
        let mut r = signed(11);
        for k in 0..4000 {
            let x = r() * 10f32.powi(k % 10);
            values.extend([x, x.round(), x.round().next_up(), x.round().next_down()]);
        }
        for x in values {
            assert_eq!(cell_floor(x), x.floor(), "{x}");
        }
        for x in [edge, edge + 256.0, 3e9_f32, 1e20, f32::MAX] {
            assert_eq!(cell_floor(x), edge, "{x}");
            assert_eq!(cell_floor(-x), -edge, "{x}");
        }
    }

    #[test]
    fn a_tilted_plane_answers_a_batch_as_each_trace_alone() {
        // A flat world's batch of sphere or line traces is computed in columns; on a ground
        // whose normal has all three components, every term of the closed form counts (on
        // a level ground two of them are products with 0). Each answer is compared bit for
        // bit with `sphere_trace`'s or `line_trace`'s.
        let rotation = Quat::from_rotation_x(0.3) * Quat::from_rotation_y(-0.2);
        let shapes = vec![(
            Pose::from_parts(Vec3::new(3.0, -2.0, 1.5), rotation),
            SharedShape::halfspace(Vec3::Z),
            None,
        )];
        let w = World::with_shapes(WorldDesc { shapes: Vec::new() }, shapes);
        assert_eq!(w.half_spaces.len(), 1);
        assert!(!w.bounded);
        let mut r = signed(5);
        let queries: Vec<SphereQuery> = (0..400)
            .map(|_| {
                let start = Vec3::new(r() * 200.0, r() * 200.0, r() * 80.0 + 20.0);
                SphereQuery {
                    start,
                    end: start + Vec3::new(r() * 60.0, r() * 60.0, r() * 100.0 - 50.0),
                    radius: 1.0 + (r() + 1.0) * 5.0,
                }
            })
            .collect();
        let bits = |h: Option<TraceHit>| {
            h.map(|h| {
                (
                    h.point.to_array().map(f32::to_bits),
                    h.normal.to_array().map(f32::to_bits),
                    h.distance.to_bits(),
                )
            })
        };
        let mut hits = vec![None; queries.len()];
        w.sphere_traces(&queries, &mut hits);
        let mut touched = 0;
        for (q, hit) in queries.iter().zip(&hits) {
            let alone = w.sphere_trace(q.start, q.end, q.radius);
            assert_eq!(bits(*hit), bits(alone), "{q:?}: {hit:?} vs {alone:?}");
            touched += usize::from(hit.is_some_and(|h| h.distance > 0.0));
        }
        assert!(touched > 50, "{touched} hits on the way");
        // The same segments as line traces, in columns too.
        let lines: Vec<LineQuery> = queries
            .iter()
            .map(|q| LineQuery {
                start: q.start,
                end: q.end,
            })
            .collect();
        w.line_traces(&lines, &mut hits);
        let mut crossed = 0;
        for (q, hit) in lines.iter().zip(&hits) {
            let alone = w.line_trace(q.start, q.end);
            assert_eq!(bits(*hit), bits(alone), "{q:?}: {hit:?} vs {alone:?}");
            crossed += usize::from(hit.is_some_and(|h| h.distance > 0.0));
        }
        assert!(crossed > 50, "{crossed} crossings on the way");
    }

    #[test]
    fn a_capsule_sweep_answers_the_nearest_shape_whatever_the_order() {
        // The mover's sweeps (a capsule, with skin, not stopping at penetration) test the
        // half-spaces apart from the bounded shapes found near the sweep, like the traces.
        // Reference: every collider cast in the order listed, without the broad phase, the
        // nearest hit kept, the collider listed first on equal distances (the world of the
        // traces' test, `tests/worlds/ties.ron`, whose box tops are flush with a ground).
        let w = World::from_str(include_str!("../tests/worlds/ties.ron"))
            .unwrap_or_else(|e| panic!("{e}"));
        let capsule = Capsule::new_z(30.0, 20.0);
        let bits = |h: SweepHit| (h.distance.to_bits(), h.normal.to_array().map(f32::to_bits));
        let mut r = signed(11);
        let mut hits = 0;
        for k in 0..400 {
            // Every other sweep from high above (the capsule's box at the start clear of the
            // box tops and the stairs, though not of the pillar) straight down.
            let (start, delta) = if k % 2 == 0 {
                let start = Vec3::new(r() * 100.0, r() * 100.0, 110.0 + r() * 10.0);
                (start, Vec3::new(0.0, 0.0, -140.0))
            } else {
                let start = Vec3::new(r() * 100.0, r() * 100.0, 55.0 + r() * 30.0);
                (start, Vec3::new(r() * 60.0, r() * 60.0, -60.0 + r() * 20.0))
            };
            let ours = w.sweep(&capsule, start, delta, 0.05, false);
            let along = Along {
                delta,
                dir: delta / delta.length(),
                length: delta.length(),
            };
            let mut reference: Option<SweepHit> = None;
            for hit in
                (w.colliders.iter()).filter_map(|c| c.cast(&capsule, start, along, 0.05, false))
            {
                if reference.is_none_or(|b| hit.distance < b.distance) {
                    reference = Some(hit);
                }
            }
            assert_eq!(
                ours.map(bits),
                reference.map(bits),
                "{start} by {delta}: {ours:?} vs {reference:?}"
            );
            hits += usize::from(ours.is_some());
        }
        assert!(hits > 300, "{hits} hits");
    }
}
