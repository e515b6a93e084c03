//! The 3D view, drawn with egui's painter from a perspective projection: the world's
//! shapes (flat-shaded triangles, sorted back to front), the skeleton, the graph's debug
//! drawing, foot trails, foot plants and sole contact points.
//!
//! World space is +Z up, centimetres. The camera orbits a target; its screen right is
//! `up × forward`, so looking along +Y (from behind a character facing +Y) the world's +X
//! — the character's left — is on the left of the screen.

use crate::recording::{RecordedFrame, Recorder};
use egui::{Color32, Pos2, Rect, Sense, Shape, Stroke, Ui, epaint::Mesh, pos2};
use glam::{Quat, Vec2, Vec3};
use strider_core::{DebugColor, DebugPrimitive, Transform};
use strider_graph::SkeletonFile;
use strider_host::report::PlantSpan;
use strider_host::world::{ShapeDesc, World};

/// Vertical field of view, degrees.
const FOV_DEG: f32 = 50.0;
/// Nearest visible distance in front of the camera, cm.
const NEAR: f32 = 5.0;
/// Ground tiles: size (cm) and how many on each side of the camera target.
const TILE: f32 = 100.0;
const TILES: i32 = 24;
/// At most this many heightfield cells along an axis are drawn (coarser rows are sampled).
const MAX_FIELD_CELLS: u32 = 48;
/// Seconds of foot trail drawn.
const TRAIL_SECONDS: f64 = 2.0;

/// The orbit camera and display toggles of the 3D view.
#[derive(Clone, Debug)]
pub struct ViewportState {
    /// Heading the camera looks towards, degrees about +Z (0 = +Y, counter-clockwise).
    pub yaw: f32,
    /// Degrees below the horizon the camera looks down.
    pub pitch: f32,
    /// Distance from the target, cm.
    pub distance: f32,
    /// The point orbited, world cm.
    pub target: Vec3,
    /// Keep the target on the character.
    pub follow: bool,
    /// Draw the graph's debug primitives.
    pub show_debug: bool,
    /// Draw foot trails and plants.
    pub show_feet: bool,
    triangles: Vec<Tri>,
    world_key: usize,
    ground: Vec<Tri>,
    ground_key: Option<(i32, i32, usize)>,
    scratch: Vec<(f32, usize)>,
    /// Where the pointer hits the ground plane at the character's height (world cm), when
    /// over the view; used to aim in strafe mode.
    pub pointer_ground: Option<Vec3>,
    /// Where the view was drawn last (screen points).
    pub rect: Rect,
}

impl Default for ViewportState {
    fn default() -> Self {
        Self {
            yaw: 0.0,
            pitch: 20.0,
            distance: 550.0,
            target: Vec3::new(0.0, 0.0, 90.0),
            follow: true,
            show_debug: true,
            show_feet: true,
            triangles: Vec::new(),
            world_key: usize::MAX,
            ground: Vec::new(),
            ground_key: None,
            scratch: Vec::new(),
            pointer_ground: None,
            rect: Rect::NOTHING,
        }
    }
}

/// A world triangle with its base colour.
#[derive(Clone, Copy, Debug)]
struct Tri {
    p: [Vec3; 3],
    color: [f32; 3],
}

/// A perspective camera for one frame of the view.
#[derive(Clone, Copy, Debug)]
pub struct Camera {
    eye: Vec3,
    forward: Vec3,
    right: Vec3,
    up: Vec3,
    focal: f32,
    center: Pos2,
}

impl Camera {
    /// The camera of `state` drawing into `rect`.
    #[must_use]
    pub fn new(state: &ViewportState, rect: Rect) -> Camera {
        let (yaw, pitch) = (state.yaw.to_radians(), state.pitch.to_radians());
        let heading = Vec3::new(-yaw.sin(), yaw.cos(), 0.0);
        let forward = (heading * pitch.cos() - Vec3::Z * pitch.sin()).normalize();
        let right = Vec3::Z.cross(forward).normalize_or(Vec3::NEG_X);
        let up = forward.cross(right);
        Camera {
            eye: state.target - forward * state.distance,
            forward,
            right,
            up,
            focal: 0.5 * rect.height() / (0.5 * FOV_DEG.to_radians()).tan(),
            center: rect.center(),
        }
    }

    /// Screen position and depth (cm in front of the camera) of world point `p`; `None`
    /// behind the near plane.
    #[must_use]
    pub fn project(&self, p: Vec3) -> Option<(Pos2, f32)> {
        let d = p - self.eye;
        let z = d.dot(self.forward);
        if z < NEAR {
            return None;
        }
        let x = d.dot(self.right) / z * self.focal;
        let y = d.dot(self.up) / z * self.focal;
        Some((pos2(self.center.x + x, self.center.y - y), z))
    }

    /// The world point at height `z` under screen position `pos`, if the ray hits it in
    /// front of the camera.
    #[must_use]
    pub fn ground_point(&self, pos: Pos2, z: f32) -> Option<Vec3> {
        let x = (pos.x - self.center.x) / self.focal;
        let y = -(pos.y - self.center.y) / self.focal;
        let dir = self.forward + self.right * x + self.up * y;
        if dir.z.abs() < 1e-6 {
            return None;
        }
        let t = (z - self.eye.z) / dir.z;
        (t > 0.0).then(|| self.eye + dir * t)
    }

    /// The camera's forward direction flattened onto the ground (unit, world XY).
    #[must_use]
    pub fn ground_forward(&self) -> Vec2 {
        Vec2::new(self.forward.x, self.forward.y).normalize_or(Vec2::Y)
    }

    /// The camera's screen-right direction on the ground (unit, world XY).
    #[must_use]
    pub fn ground_right(&self) -> Vec2 {
        Vec2::new(self.right.x, self.right.y).normalize_or(Vec2::NEG_X)
    }
}

/// What the view shows for one frame: a recorded frame and the session's fixed data.
pub struct Scene<'a> {
    /// The frame drawn (the newest when live).
    pub frame: &'a RecordedFrame,
    /// The recording (for the foot trails).
    pub recorder: &'a Recorder,
    /// The world.
    pub world: &'a World,
    /// The skeleton (bone parents, contact points).
    pub skeleton: &'a SkeletonFile,
    /// Foot bones (skeleton order indices) for trails.
    pub feet: &'a [usize],
    /// Planted spans of the quality report (world XY).
    pub plants: &'a [PlantSpan],
}

fn color(c: [f32; 3], light: f32) -> Color32 {
    let f = |x: f32| (x * light * 255.0).clamp(0.0, 255.0) as u8;
    Color32::from_rgb(f(c[0]), f(c[1]), f(c[2]))
}

fn debug_color(c: DebugColor) -> Color32 {
    let [r, g, b, a] = c.0;
    Color32::from_rgba_unmultiplied(
        (r * 255.0) as u8,
        (g * 255.0) as u8,
        (b * 255.0) as u8,
        (a * 255.0) as u8,
    )
}

fn push_quad(out: &mut Vec<Tri>, a: Vec3, b: Vec3, c: Vec3, d: Vec3, color: [f32; 3]) {
    out.push(Tri {
        p: [a, b, c],
        color,
    });
    out.push(Tri {
        p: [a, c, d],
        color,
    });
}

/// The 8 corners of a box, bottom 4 then top 4, counter-clockwise seen from above.
fn box_corners(center: Vec3, half: Vec3, rotation: Quat) -> [Vec3; 8] {
    let c =
        |x: f32, y: f32, z: f32| center + rotation * Vec3::new(x * half.x, y * half.y, z * half.z);
    [
        c(-1.0, -1.0, -1.0),
        c(1.0, -1.0, -1.0),
        c(1.0, 1.0, -1.0),
        c(-1.0, 1.0, -1.0),
        c(-1.0, -1.0, 1.0),
        c(1.0, -1.0, 1.0),
        c(1.0, 1.0, 1.0),
        c(-1.0, 1.0, 1.0),
    ]
}

fn push_box(out: &mut Vec<Tri>, center: Vec3, half: Vec3, rotation: Quat, color: [f32; 3]) {
    let k = box_corners(center, half, rotation);
    let faces = [
        [0, 1, 2, 3],
        [4, 5, 6, 7],
        [0, 1, 5, 4],
        [1, 2, 6, 5],
        [2, 3, 7, 6],
        [3, 0, 4, 7],
    ];
    for f in faces {
        push_quad(out, k[f[0]], k[f[1]], k[f[2]], k[f[3]], color);
    }
}

const SOLID: [f32; 3] = [0.62, 0.6, 0.56];
const STEP: [f32; 3] = [0.58, 0.6, 0.66];
const FIELD: [f32; 3] = [0.45, 0.58, 0.42];

/// Triangles of every shape but the infinite ground (drawn as tiles around the camera).
fn world_triangles(world: &World, out: &mut Vec<Tri>) {
    out.clear();
    for shape in &world.desc().shapes {
        match *shape {
            ShapeDesc::Ground { .. } => {}
            ShapeDesc::Box { .. } | ShapeDesc::Platform { .. } | ShapeDesc::Stairs { .. } => {
                // The boxes the world collides with; steps alternate in shade.
                let stairs = matches!(shape, ShapeDesc::Stairs { .. });
                for (i, b) in shape.solid_boxes().enumerate() {
                    let color = if stairs && i % 2 == 0 { STEP } else { SOLID };
                    push_box(out, b.center, b.half_extents, b.rotation, color);
                }
            }
            ShapeDesc::Ramp { start, yaw, .. } => {
                let Some(corners) = shape.ramp_corners() else {
                    continue;
                };
                let r = Quat::from_rotation_z(yaw.to_radians());
                let [nl, nr, fl, fr, tl, tr] = corners.map(|c| Vec3::from(start) + r * c);
                push_quad(out, nl, nr, tr, tl, SOLID);
                push_quad(out, fl, fr, tr, tl, SOLID);
                out.push(Tri {
                    p: [nl, fl, tl],
                    color: SOLID,
                });
                out.push(Tri {
                    p: [nr, fr, tr],
                    color: SOLID,
                });
            }
            ShapeDesc::Heightfield { cells, .. } => {
                let (cx, cy) = (cells.0.max(1), cells.1.max(1));
                let sx = cx.div_ceil(MAX_FIELD_CELLS).max(1);
                let sy = cy.div_ceil(MAX_FIELD_CELLS).max(1);
                // The collision mesh's own vertices (every sx-th, sy-th when drawn coarser).
                let vertex = |i: u32, j: u32| shape.heightfield_vertex(i, j).unwrap_or_default();
                let mut j = 0;
                while j < cy {
                    let mut i = 0;
                    while i < cx {
                        let shade = if ((i / sx) + (j / sy)) % 2 == 0 {
                            FIELD
                        } else {
                            [FIELD[0] * 0.92, FIELD[1] * 0.92, FIELD[2] * 0.92]
                        };
                        push_quad(
                            out,
                            vertex(i, j),
                            vertex(i + sx, j),
                            vertex(i + sx, j + sy),
                            vertex(i, j + sy),
                            shade,
                        );
                        i += sx;
                    }
                    j += sy;
                }
            }
        }
    }
}

/// Shows the 3D view of `scene` filling `ui`'s available space; handles the camera
/// (drag: orbit, right or middle drag: pan, scroll: zoom). Returns the view's response.
pub fn show(ui: &mut Ui, state: &mut ViewportState, scene: &Scene<'_>) -> egui::Response {
    let (rect, response) = ui.allocate_exact_size(ui.available_size(), Sense::click_and_drag());
    state.rect = rect;
    let to_world = scene.frame.meta.to_world;
    if state.follow {
        let at = to_world.translation + Vec3::Z * 90.0;
        state.target = state.target.lerp(at, 0.2);
    }
    if response.dragged_by(egui::PointerButton::Primary) {
        let d = response.drag_delta();
        state.yaw -= d.x * 0.3;
        state.pitch = (state.pitch + d.y * 0.3).clamp(-10.0, 89.0);
    }
    if response.dragged_by(egui::PointerButton::Secondary)
        || response.dragged_by(egui::PointerButton::Middle)
    {
        let d = response.drag_delta();
        let cam = Camera::new(state, rect);
        let scale = state.distance / cam.focal;
        state.target += (-cam.right * d.x + cam.up * d.y) * scale;
        state.follow = false;
    }
    if response.hovered() {
        let scroll = ui.input(|i| i.smooth_scroll_delta.y);
        if scroll != 0.0 {
            state.distance = (state.distance * (-scroll * 0.002).exp()).clamp(50.0, 5000.0);
        }
    }
    let cam = Camera::new(state, rect);
    state.pointer_ground = response
        .hover_pos()
        .and_then(|p| cam.ground_point(p, to_world.translation.z));

    let painter = ui.painter_at(rect);
    painter.rect_filled(rect, 0.0, Color32::from_rgb(34, 38, 46));

    let key = std::ptr::from_ref(scene.world.desc()) as usize ^ scene.world.desc().shapes.len();
    if key != state.world_key {
        world_triangles(scene.world, &mut state.triangles);
        state.world_key = key;
    }
    let light = Vec3::new(0.35, -0.5, 1.0).normalize();
    let mut mesh = Mesh::default();
    // Ground tiles around the camera target, rebuilt when the target crosses a tile.
    let (cx, cy) = (
        (state.target.x / TILE).floor() as i32,
        (state.target.y / TILE).floor() as i32,
    );
    if state.ground_key != Some((cx, cy, key)) {
        state.ground_key = Some((cx, cy, key));
        state.ground.clear();
        for shape in &scene.world.desc().shapes {
            if let ShapeDesc::Ground { height } = *shape {
                for j in -TILES..TILES {
                    for i in -TILES..TILES {
                        let (x0, y0) = ((cx + i) as f32 * TILE, (cy + j) as f32 * TILE);
                        let c = if (cx + i + cy + j).rem_euclid(2) == 0 {
                            [0.52, 0.52, 0.5]
                        } else {
                            [0.47, 0.47, 0.45]
                        };
                        let p = |x: f32, y: f32| Vec3::new(x, y, height);
                        push_quad(
                            &mut state.ground,
                            p(x0, y0),
                            p(x0 + TILE, y0),
                            p(x0 + TILE, y0 + TILE),
                            p(x0, y0 + TILE),
                            c,
                        );
                    }
                }
            }
        }
    }
    let count = state.ground.len() + state.triangles.len();
    mesh.reserve_vertices(3 * count);
    mesh.reserve_triangles(count);
    // Ground first (it is below everything), then the shapes sorted back to front.
    add_tris(&mut mesh, &cam, &state.ground, light, None);
    state.scratch.clear();
    for (i, t) in state.triangles.iter().enumerate() {
        let centroid = (t.p[0] + t.p[1] + t.p[2]) / 3.0;
        state
            .scratch
            .push(((centroid - cam.eye).dot(cam.forward), i));
    }
    state.scratch.sort_by(|a, b| b.0.total_cmp(&a.0));
    add_tris(
        &mut mesh,
        &cam,
        &state.triangles,
        light,
        Some(&state.scratch),
    );
    painter.add(Shape::mesh(mesh));

    let line = |a: Vec3, b: Vec3, stroke: Stroke| {
        if let (Some((pa, _)), Some((pb, _))) = (cam.project(a), cam.project(b)) {
            painter.line_segment([pa, pb], stroke);
        }
    };
    let dot = |p: Vec3, radius: f32, color: Color32| {
        if let Some((pp, _)) = cam.project(p) {
            painter.circle_filled(pp, radius, color);
        }
    };

    // Foot trails and plants.
    if state.show_feet {
        let now = scene.frame.meta.time;
        for (k, &foot) in scene.feet.iter().enumerate() {
            let tint = if k % 2 == 0 {
                Color32::from_rgb(255, 120, 90)
            } else {
                Color32::from_rgb(90, 170, 255)
            };
            let mut previous: Option<Vec3> = None;
            for f in scene.recorder.iter().rev() {
                if f.meta.time > now {
                    continue;
                }
                if now - f.meta.time > TRAIL_SECONDS {
                    break;
                }
                let Some(g) = f.globals.get(foot) else { break };
                let p = f.meta.to_world.transform_point(g.translation);
                if let Some(q) = previous {
                    let fade = 1.0 - ((now - f.meta.time) / TRAIL_SECONDS) as f32;
                    line(q, p, Stroke::new(2.0, tint.gamma_multiply(fade.max(0.1))));
                }
                previous = Some(p);
            }
        }
        for span in scene.plants {
            let z = scene
                .world
                .ground_height(
                    span.position.x,
                    span.position.y,
                    to_world.translation.z + 100.0,
                )
                .map_or(0.0, |(z, _)| z);
            let c = Vec3::new(span.position.x, span.position.y, z + 0.5);
            let tint = if span.leg % 2 == 0 {
                Color32::from_rgb(255, 120, 90)
            } else {
                Color32::from_rgb(90, 170, 255)
            };
            let r = 6.0;
            for a in 0..8 {
                let t0 = a as f32 / 8.0 * std::f32::consts::TAU;
                let t1 = (a + 1) as f32 / 8.0 * std::f32::consts::TAU;
                line(
                    c + Vec3::new(t0.cos(), t0.sin(), 0.0) * r,
                    c + Vec3::new(t1.cos(), t1.sin(), 0.0) * r,
                    Stroke::new(1.5, tint),
                );
            }
        }
    }

    // Skeleton.
    let globals = &scene.frame.globals;
    let skel = &scene.skeleton.skeleton;
    let bone_world = |i: usize| to_world.transform_point(globals[i].translation);
    for i in 0..globals.len().min(skel.len()) {
        if let Some(parent) = skel.parent(strider_core::BoneIndex(i as u32)) {
            line(
                bone_world(parent.0 as usize),
                bone_world(i),
                Stroke::new(3.0, Color32::from_rgb(235, 225, 200)),
            );
        }
        dot(bone_world(i), 3.0, Color32::from_rgb(250, 200, 80));
    }
    // Sole contact points: green on the ground (within 1 cm), grey above it.
    for c in &scene.skeleton.contacts {
        if let Some(b) = skel.find(&c.bone)
            && let Some(g) = globals.get(b.0 as usize)
        {
            let p = to_world.transform_point(g.transform_point(c.offset));
            let ground = scene
                .world
                .ground_height(p.x, p.y, p.z + 30.0)
                .map(|(z, _)| z);
            let on = ground.is_some_and(|z| (p.z - z).abs() <= 1.0);
            dot(
                p,
                3.5,
                if on {
                    Color32::from_rgb(80, 230, 120)
                } else {
                    Color32::from_gray(170)
                },
            );
        }
    }
    // The capsule's velocity.
    let v = scene.frame.meta.velocity;
    if v.length_squared() > 1.0 {
        let base = to_world.translation + Vec3::Z * 2.0;
        arrow(
            &line,
            base,
            base + v * 0.3,
            Stroke::new(2.0, Color32::YELLOW),
        );
    }
    // The graph's debug drawing (rig space).
    if state.show_debug {
        for p in &scene.frame.debug {
            draw_debug(p, &to_world, &line, &dot);
        }
    }
    // Axes at the world origin: X red, Y green, Z blue, 50 cm.
    for (axis, c) in [
        (Vec3::X, Color32::RED),
        (Vec3::Y, Color32::GREEN),
        (Vec3::Z, Color32::LIGHT_BLUE),
    ] {
        line(Vec3::ZERO, axis * 50.0, Stroke::new(2.0, c));
    }
    axes_gizmo(&painter, &cam, rect);
    response
}

fn add_tris(
    mesh: &mut Mesh,
    cam: &Camera,
    tris: &[Tri],
    light: Vec3,
    order: Option<&[(f32, usize)]>,
) {
    let mut emit = |t: &Tri| {
        let (Some(a), Some(b), Some(c)) = (
            cam.project(t.p[0]),
            cam.project(t.p[1]),
            cam.project(t.p[2]),
        ) else {
            return;
        };
        let mut n = (t.p[1] - t.p[0]).cross(t.p[2] - t.p[0]).normalize_or_zero();
        if n.dot(cam.eye - t.p[0]) < 0.0 {
            n = -n;
        }
        let shade = 0.45 + 0.55 * n.dot(light).max(0.0);
        let col = color(t.color, shade);
        let base = mesh.vertices.len() as u32;
        for p in [a.0, b.0, c.0] {
            mesh.colored_vertex(p, col);
        }
        mesh.add_triangle(base, base + 1, base + 2);
    };
    match order {
        Some(order) => order.iter().for_each(|&(_, i)| emit(&tris[i])),
        None => tris.iter().for_each(&mut emit),
    }
}

fn arrow(line: &impl Fn(Vec3, Vec3, Stroke), a: Vec3, b: Vec3, stroke: Stroke) {
    line(a, b, stroke);
    let d = b - a;
    let len = d.length();
    if len < 1e-3 {
        return;
    }
    let dir = d / len;
    let side = dir.cross(Vec3::Z).normalize_or(Vec3::X) * len * 0.12;
    let back = b - dir * len * 0.2;
    line(b, back + side, stroke);
    line(b, back - side, stroke);
}

fn draw_debug(
    p: &DebugPrimitive,
    to_world: &Transform,
    line: &impl Fn(Vec3, Vec3, Stroke),
    dot: &impl Fn(Vec3, f32, Color32),
) {
    let w = |v: Vec3| to_world.transform_point(v);
    let width = |t: f32| t.clamp(1.0, 4.0);
    match *p {
        DebugPrimitive::Point {
            position,
            size,
            color,
        } => dot(
            w(position),
            (size * 0.5).clamp(2.0, 8.0),
            debug_color(color),
        ),
        DebugPrimitive::Line {
            start,
            end,
            thickness,
            color,
        } => line(
            w(start),
            w(end),
            Stroke::new(width(thickness), debug_color(color)),
        ),
        DebugPrimitive::Arrow {
            start,
            end,
            thickness,
            color,
        } => arrow(
            line,
            w(start),
            w(end),
            Stroke::new(width(thickness), debug_color(color)),
        ),
        DebugPrimitive::Sphere {
            center,
            radius,
            color,
        } => {
            let c = w(center);
            let stroke = Stroke::new(1.0, debug_color(color));
            for (u, v) in [(Vec3::X, Vec3::Y), (Vec3::X, Vec3::Z), (Vec3::Y, Vec3::Z)] {
                for a in 0..12 {
                    let t0 = a as f32 / 12.0 * std::f32::consts::TAU;
                    let t1 = (a + 1) as f32 / 12.0 * std::f32::consts::TAU;
                    line(
                        c + (u * t0.cos() + v * t0.sin()) * radius,
                        c + (u * t1.cos() + v * t1.sin()) * radius,
                        stroke,
                    );
                }
            }
        }
        DebugPrimitive::Box {
            transform,
            half_extents,
            color,
        } => {
            let k = box_corners(Vec3::ZERO, half_extents, Quat::IDENTITY)
                .map(|c| w(transform.transform_point(c)));
            let stroke = Stroke::new(1.0, debug_color(color));
            for (a, b) in [
                (0, 1),
                (1, 2),
                (2, 3),
                (3, 0),
                (4, 5),
                (5, 6),
                (6, 7),
                (7, 4),
                (0, 4),
                (1, 5),
                (2, 6),
                (3, 7),
            ] {
                line(k[a], k[b], stroke);
            }
        }
        DebugPrimitive::Axes {
            transform,
            size,
            thickness,
        } => {
            let o = w(transform.translation);
            for (axis, c) in [
                (Vec3::X, Color32::RED),
                (Vec3::Y, Color32::GREEN),
                (Vec3::Z, Color32::LIGHT_BLUE),
            ] {
                let tip = w(transform
                    .transform_point(axis * size / transform.scale.max_element().max(1e-6)));
                line(o, tip, Stroke::new(width(thickness), c));
            }
        }
    }
}

/// Small axes in the view's corner: the world's X (red), Y (green), Z (blue) as seen from
/// the camera.
fn axes_gizmo(painter: &egui::Painter, cam: &Camera, rect: Rect) {
    let origin = pos2(rect.left() + 40.0, rect.bottom() - 40.0);
    for (axis, c, label) in [
        (Vec3::X, Color32::RED, "X"),
        (Vec3::Y, Color32::GREEN, "Y"),
        (Vec3::Z, Color32::LIGHT_BLUE, "Z"),
    ] {
        let tip = origin + egui::vec2(axis.dot(cam.right), -axis.dot(cam.up)) * 28.0;
        painter.line_segment([origin, tip], Stroke::new(2.0, c));
        painter.text(
            tip,
            egui::Align2::CENTER_CENTER,
            label,
            egui::FontId::proportional(12.0),
            c,
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn camera(yaw: f32) -> Camera {
        let state = ViewportState {
            yaw,
            pitch: 0.0,
            distance: 500.0,
            target: Vec3::ZERO,
            ..ViewportState::default()
        };
        Camera::new(
            &state,
            Rect::from_min_size(Pos2::ZERO, egui::vec2(800.0, 600.0)),
        )
    }

    #[test]
    fn seen_from_behind_the_characters_left_is_on_screen_left() {
        // Yaw 0 looks along +Y, as from behind a character facing +Y; its left is +X.
        let cam = camera(0.0);
        let (left, _) = cam.project(Vec3::new(50.0, 0.0, 0.0)).expect("visible");
        let (right, _) = cam.project(Vec3::new(-50.0, 0.0, 0.0)).expect("visible");
        assert!(left.x < 400.0 && right.x > 400.0, "{left:?} {right:?}");
        // +Z is up on screen.
        let (up, _) = cam.project(Vec3::new(0.0, 0.0, 50.0)).expect("visible");
        assert!(up.y < 300.0);
        // The target is at the centre, 500 cm deep.
        let (c, depth) = cam.project(Vec3::ZERO).expect("visible");
        assert!((c.x - 400.0).abs() < 1e-3 && (c.y - 300.0).abs() < 1e-3);
        assert!((depth - 500.0).abs() < 1e-3);
        // Behind the camera: not drawn.
        assert!(cam.project(Vec3::new(0.0, -600.0, 0.0)).is_none());
    }

    #[test]
    fn ground_directions_follow_the_camera_yaw() {
        let cam = camera(90.0);
        // Yaw 90° looks along −X; screen right (up × forward) is then −Y, as −X is at
        // yaw 0.
        assert!((cam.ground_forward() - Vec2::NEG_X).length() < 1e-5);
        assert!((cam.ground_right() - Vec2::NEG_Y).length() < 1e-5);
    }

    #[test]
    fn the_pointer_ray_meets_the_ground_under_it() {
        let mut state = ViewportState {
            pitch: 30.0,
            target: Vec3::new(10.0, 20.0, 0.0),
            ..ViewportState::default()
        };
        state.yaw = 45.0;
        let rect = Rect::from_min_size(Pos2::ZERO, egui::vec2(800.0, 600.0));
        let cam = Camera::new(&state, rect);
        let p = cam.ground_point(rect.center(), 0.0).expect("looking down");
        assert!((p - state.target).length() < 1e-2, "{p:?}");
    }
}
