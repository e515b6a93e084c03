//! Traces against hand-computed values.

use glam::Vec3;
use strider_core::{
    HitColumns, LineQuery, SphereQuery, TRACE_COLUMNS, TraceColumns, TraceHit, WorldQuery,
};
use strider_host::world::{ShapeDesc, Wave, World, WorldDesc, WorldError, wave_height};

fn near(a: f32, b: f32, tol: f32) -> bool {
    (a - b).abs() <= tol
}

fn assert_vec_near(a: Vec3, b: Vec3, tol: f32) {
    assert!((a - b).length() <= tol, "{a} != {b} (tolerance {tol})");
}

fn world(text: &str) -> World {
    World::from_str(text).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn line_trace_onto_a_20_degree_ramp() {
    // Rising along +Y: the top is z = y · tan 20°, normal (0, −sin 20°, cos 20°).
    let w = world(
        "(shapes: [Ramp(start: (0.0, 0.0, 0.0), yaw: 0.0, angle: 20.0, length: 300.0, width: 200.0)])",
    );
    let (s, c) = 20f32.to_radians().sin_cos();
    let top = 150.0 * 20f32.to_radians().tan(); // 54.596
    let hit = w
        .line_trace(Vec3::new(10.0, 150.0, 200.0), Vec3::new(10.0, 150.0, -10.0))
        .expect("hit");
    assert_vec_near(hit.point, Vec3::new(10.0, 150.0, top), 1e-3);
    assert_vec_near(hit.normal, Vec3::new(0.0, -s, c), 1e-4);
    assert!(near(hit.distance, 200.0 - top, 1e-3), "{}", hit.distance);

    // Yaw −90° rises along +X (yaw 90° would be −X): normal (−sin 20°, 0, cos 20°).
    let w = world(
        "(shapes: [Ramp(start: (0.0, 0.0, 0.0), yaw: -90.0, angle: 20.0, length: 300.0, width: 200.0)])",
    );
    let hit = w
        .line_trace(
            Vec3::new(100.0, 30.0, 100.0),
            Vec3::new(100.0, 30.0, -100.0),
        )
        .expect("hit");
    assert_vec_near(
        hit.point,
        Vec3::new(100.0, 30.0, 100.0 * 20f32.to_radians().tan()),
        1e-3,
    );
    assert_vec_near(hit.normal, Vec3::new(-s, 0.0, c), 1e-4);
    // The ramp's top edge: 300 · tan 20° high, a vertical face beyond.
    let (h, _) = w.ground_height(299.0, 0.0, 500.0).expect("ramp");
    assert!(near(h, 299.0 * 20f32.to_radians().tan(), 1e-2));
    assert!(w.ground_height(301.0, 0.0, 500.0).is_none());
}

#[test]
fn sphere_trace_onto_a_floor_travels_drop_minus_radius() {
    let w = world("(shapes: [Ground(height: 5.0)])");
    let hit = w
        .sphere_trace(Vec3::new(3.0, 4.0, 105.0), Vec3::new(3.0, 4.0, -95.0), 10.0)
        .expect("hit");
    assert!(near(hit.distance, 100.0 - 10.0, 1e-3), "{}", hit.distance);
    assert_vec_near(hit.point, Vec3::new(3.0, 4.0, 5.0), 1e-3);
    assert_vec_near(hit.normal, Vec3::Z, 1e-5);
    // Too short to reach.
    assert!(
        w.sphere_trace(Vec3::new(0.0, 0.0, 105.0), Vec3::new(0.0, 0.0, 20.0), 10.0)
            .is_none()
    );
    // Radius 0 is a line trace.
    let line = w
        .sphere_trace(Vec3::new(0.0, 0.0, 105.0), Vec3::new(0.0, 0.0, -95.0), 0.0)
        .expect("hit");
    assert!(near(line.distance, 100.0, 1e-3));
}

#[test]
fn sphere_trace_against_a_wall_box() {
    // A box whose −Y face is the plane y = 100.
    let w =
        world("(shapes: [Box(center: (0.0, 150.0, 100.0), half_extents: (200.0, 50.0, 100.0))])");
    let hit = w
        .sphere_trace(Vec3::new(0.0, 0.0, 50.0), Vec3::new(0.0, 300.0, 50.0), 20.0)
        .expect("hit");
    assert!(near(hit.distance, 80.0, 1e-3), "{}", hit.distance);
    assert_vec_near(hit.normal, Vec3::NEG_Y, 1e-4);
    assert_vec_near(hit.point, Vec3::new(0.0, 100.0, 50.0), 1e-2);
}

#[test]
fn every_shape_of_a_crowded_world_is_found() {
    // Eleven pillars of heights 10, 20, .. 110 cm along x (one every 100 cm), with the
    // ground listed among them: the world tests its shapes four at a time, and a trace
    // straight down onto pillar k must stop on its top, at the height only that pillar
    // has, whichever group it falls in.
    let mut shapes: Vec<String> = (0..11)
        .map(|k| {
            let h = 10.0 * (k + 1) as f32;
            format!(
                "Box(center: ({}.0, 0.0, {}), half_extents: (20.0, 20.0, {}))",
                100 * k,
                h / 2.0,
                h / 2.0
            )
        })
        .collect();
    shapes.insert(6, "Ground(height: 0.0)".to_string());
    let w = world(&format!("(shapes: [{}])", shapes.join(", ")));
    for k in 0..11 {
        let x = 100.0 * k as f32;
        let top = 10.0 * (k + 1) as f32;
        let down = |from: Vec3| from - Vec3::Z * 300.0;
        let from = Vec3::new(x + 5.0, -3.0, 250.0);
        let hit = w
            .line_trace(from, down(from))
            .expect("a line onto the pillar");
        assert!(near(hit.point.z, top, 1e-3), "pillar {k}: {hit:?}");
        let hit = w
            .sphere_trace(from, down(from), 4.0)
            .expect("a ball onto the pillar");
        assert!(near(hit.point.z, top, 1e-3), "pillar {k}: {hit:?}");
        assert_vec_near(hit.normal, Vec3::Z, 1e-4);
        // Between the pillars: the ground.
        let gap = Vec3::new(x + 50.0, 0.0, 250.0);
        let hit = w
            .sphere_trace(gap, down(gap), 4.0)
            .expect("a ball onto the ground");
        assert!(near(hit.point.z, 0.0, 1e-3), "after pillar {k}: {hit:?}");
    }
}

#[test]
fn the_nearest_shape_answers_whatever_the_order() {
    // A world answers a trace with the nearest of its shapes' hits, the shape listed first
    // on equal distances (`tests/worlds/ties.ron` says how its shapes tie). Reference: each
    // shape in a world of its own, the nearest hit picked by hand. Each trace's start is
    // also traced by a sphere that does not move (the overlap test, through the general
    // sweep), often touching two shapes at distance 0.
    let w = world(include_str!("worlds/ties.ron"));
    let alone: Vec<World> = (w.desc().shapes.iter())
        .map(|shape| {
            World::from_desc(&WorldDesc {
                shapes: vec![shape.clone()],
            })
        })
        .collect();
    assert_eq!(alone.len(), 8);
    let nearest = |each: &dyn Fn(&World) -> Option<strider_core::TraceHit>| {
        let mut best: Option<strider_core::TraceHit> = None;
        for hit in alone.iter().filter_map(each) {
            if best.is_none_or(|b| hit.distance < b.distance) {
                best = Some(hit);
            }
        }
        best
    };
    let same = |a, b| hit_bits(a) == hit_bits(b);
    let mut next = uniform(7);
    let (mut hits, mut ground_hits, mut overlaps) = (0, 0, 0);
    for k in 0..3000 {
        let mut r = || next() * 2.0 - 1.0;
        let start = Vec3::new(r() * 120.0, r() * 120.0, 40.0 + r() * 60.0);
        let end = start + Vec3::new(r() * 40.0, r() * 40.0, -120.0 + r() * 40.0);
        // Every fourth trace straight down onto the flush box's top or the ground by it,
        // and every fourth from whole centimetres onto a flush step of turned stairs, the
        // flight listed after the ground and the one listed before it in turn.
        let (start, end) = match k % 4 {
            0 => {
                let at = Vec3::new(r() * 40.0, r() * 40.0, 50.0);
                (at, at - Vec3::Z * 100.0)
            }
            2 => {
                let side = if k % 8 == 2 { 90.0 } else { -90.0 };
                let at = Vec3::new(
                    (side + r() * 30.0).round(),
                    (80.0 + r() * 30.0).round(),
                    50.0,
                );
                (at, at - Vec3::Z * 100.0)
            }
            _ => (start, end),
        };
        let radius = 3.5 + r() * 3.0;
        let ours = w.sphere_trace(start, end, radius);
        let reference = nearest(&|one: &World| one.sphere_trace(start, end, radius));
        assert!(
            same(ours, reference),
            "sphere {start} -> {end} r {radius}: {ours:?} vs {reference:?}"
        );
        let ours = w.line_trace(start, end);
        let reference = nearest(&|one: &World| one.line_trace(start, end));
        assert!(
            same(ours, reference),
            "line {start} -> {end}: {ours:?} vs {reference:?}"
        );
        if let Some(hit) = ours {
            hits += 1;
            ground_hits += usize::from(hit.point.z.abs() < 1e-3 && hit.normal == Vec3::Z);
        }
        // A sphere that does not move: the overlap at its start, often with two shapes at
        // distance 0 (a ball on the flush box's edge touches the box and the ground).
        let at = Vec3::new(start.x, start.y, r() * 8.0);
        let ours = w.sphere_trace(at, at, radius);
        let reference = nearest(&|one: &World| one.sphere_trace(at, at, radius));
        assert!(
            same(ours, reference),
            "overlap at {at} r {radius}: {ours:?} vs {reference:?}"
        );
        overlaps += usize::from(ours.is_some());
    }
    assert!(
        hits > 2000 && ground_hits > 300 && overlaps > 1000,
        "{hits} hits, {ground_hits} on the ground or flush tops, {overlaps} overlaps"
    );
}

#[test]
fn rotated_box_face() {
    // Half extents (10, 50, 10) turned by 90°: the long axis lies along X, the box spans
    // y ∈ [−10, 10].
    let w = world(
        "(shapes: [Box(center: (0.0, 0.0, 10.0), half_extents: (10.0, 50.0, 10.0), yaw: 90.0)])",
    );
    let hit = w
        .line_trace(Vec3::new(40.0, -100.0, 10.0), Vec3::new(40.0, 100.0, 10.0))
        .expect("hit");
    assert!(near(hit.point.y, -10.0, 1e-3));
    assert_vec_near(hit.normal, Vec3::NEG_Y, 1e-4);
    assert!(
        w.line_trace(Vec3::new(60.0, -100.0, 10.0), Vec3::new(60.0, 100.0, 10.0))
            .is_none()
    );
}

#[test]
fn stair_step_tops() {
    let w = world(
        "(shapes: [Ground(height: 0.0), Stairs(start: (0.0, 0.0, 0.0), yaw: 0.0, width: 200.0, \
         steps: 8, rise: 15.0, run: 30.0, landing: 100.0)])",
    );
    for i in 0..8 {
        let y = 30.0 * i as f32 + 15.0;
        let (h, n) = w.ground_height(0.0, y, 500.0).expect("step");
        assert!(near(h, 15.0 * (i + 1) as f32, 1e-3), "step {i}: {h}");
        assert_vec_near(n, Vec3::Z, 1e-5);
    }
    let (landing, _) = w
        .ground_height(50.0, 8.0 * 30.0 + 90.0, 500.0)
        .expect("landing");
    assert!(near(landing, 120.0, 1e-3));
    let (before, _) = w.ground_height(0.0, -5.0, 500.0).expect("ground");
    assert!(near(before, 0.0, 1e-4));
    let (beyond, _) = w
        .ground_height(0.0, 8.0 * 30.0 + 101.0, 500.0)
        .expect("ground");
    assert!(near(beyond, 0.0, 1e-4));
    // The first riser faces −Y.
    let hit = w
        .line_trace(Vec3::new(0.0, -50.0, 10.0), Vec3::new(0.0, 50.0, 10.0))
        .expect("riser");
    assert!(near(hit.point.y, 0.0, 1e-3));
    assert_vec_near(hit.normal, Vec3::NEG_Y, 1e-4);
}

#[test]
fn stairs_turned_by_yaw() {
    // Yaw 180°: rising along −Y from y = 0.
    let w = world(
        "(shapes: [Stairs(start: (0.0, 0.0, 10.0), yaw: 180.0, width: 100.0, steps: 2, rise: 20.0, run: 40.0)])",
    );
    let (h0, _) = w.ground_height(0.0, -20.0, 500.0).expect("step 0");
    let (h1, _) = w.ground_height(0.0, -60.0, 500.0).expect("step 1");
    assert!(near(h0, 30.0, 1e-3) && near(h1, 50.0, 1e-3), "{h0} {h1}");
    assert!(w.ground_height(0.0, 20.0, 500.0).is_none());
}

#[test]
fn platform_top_and_edges() {
    let w =
        world("(shapes: [Platform(center: (100.0, 0.0), half_size: (50.0, 200.0), top: 20.0)])");
    assert!(near(
        w.ground_height(100.0, 0.0, 100.0).unwrap().0,
        20.0,
        1e-4
    ));
    assert!(near(
        w.ground_height(149.0, 199.0, 100.0).unwrap().0,
        20.0,
        1e-4
    ));
    assert!(w.ground_height(151.0, 0.0, 100.0).is_none());
}

#[test]
fn heightfield_matches_the_generator_at_grid_points() {
    let waves = vec![
        Wave {
            amplitude: 3.0,
            wavelength: 250.0,
            heading: 30.0,
            phase: 0.0,
        },
        Wave {
            amplitude: 1.5,
            wavelength: 90.0,
            heading: -70.0,
            phase: 45.0,
        },
    ];
    let (nx, ny) = (20u32, 10u32);
    let heights: Vec<f32> = (0..(nx + 1) * (ny + 1)).map(|i| (i % 7) as f32).collect();
    let desc = WorldDesc {
        shapes: vec![ShapeDesc::Heightfield {
            origin: (-500.0, -250.0, 2.0),
            size: (1000.0, 500.0),
            cells: (nx, ny),
            heights: heights.clone(),
            waves: waves.clone(),
        }],
    };
    let w = World::try_from_desc(&desc).expect("valid");
    for j in 0..=ny {
        for i in 0..=nx {
            let x = -500.0 + 50.0 * i as f32;
            let y = -250.0 + 50.0 * j as f32;
            let expected = 2.0
                + heights[(j * (nx + 1) + i) as usize]
                + waves
                    .iter()
                    .map(|w| {
                        let (s, c) = w.heading.to_radians().sin_cos();
                        let along = -s * (x + 500.0) + c * (y + 250.0);
                        w.amplitude
                            * (std::f32::consts::TAU * along / w.wavelength + w.phase.to_radians())
                                .sin()
                    })
                    .sum::<f32>();
            assert!(near(
                wave_height(&waves, (-500.0, -250.0), x, y)
                    + 2.0
                    + heights[(j * (nx + 1) + i) as usize],
                expected,
                1e-3
            ));
            // Nudge inside the grid so the ray never grazes the outer boundary.
            let xi = x.clamp(-499.99, 499.99);
            let yi = y.clamp(-249.99, 249.99);
            let (h, n) = w.ground_height(xi, yi, 100.0).expect("heightfield");
            assert!(near(h, expected, 0.05), "({i}, {j}): {h} vs {expected}");
            assert!(n.z > 0.5);
        }
    }
    // The surface is hit from above with an upward normal, even by a sphere.
    let hit = w
        .sphere_trace(
            Vec3::new(0.0, 0.0, 100.0),
            Vec3::new(0.0, 0.0, -100.0),
            10.0,
        )
        .expect("hit");
    assert!(hit.normal.z > 0.9 && hit.distance > 50.0);
}

#[test]
fn traces_are_deterministic_and_miss_the_void() {
    let w = world("(shapes: [])");
    assert!(w.line_trace(Vec3::ZERO, Vec3::NEG_Z * 1000.0).is_none());
    assert!(
        w.sphere_trace(Vec3::ZERO, Vec3::NEG_Z * 1000.0, 10.0)
            .is_none()
    );
    assert!(w.ground_height(0.0, 0.0, 0.0).is_none());

    let w = world(
        "(shapes: [Ground(height: 0.0), Ramp(start: (0.0, 0.0, 0.0), angle: 25.0, length: 200.0, width: 100.0)])",
    );
    let a = w.sphere_trace(
        Vec3::new(3.0, 77.0, 300.0),
        Vec3::new(-20.0, 100.0, -50.0),
        12.0,
    );
    let b = w.sphere_trace(
        Vec3::new(3.0, 77.0, 300.0),
        Vec3::new(-20.0, 100.0, -50.0),
        12.0,
    );
    assert_eq!(a, b);
    assert!(a.is_some());
}

#[test]
fn degenerate_traces_do_not_panic() {
    let w = world("(shapes: [Ground(height: 0.0)])");
    assert!(w.line_trace(Vec3::ONE, Vec3::ONE).is_none());
    assert!(w.line_trace(Vec3::NAN, Vec3::ONE).is_none());
    assert!(w.sphere_trace(Vec3::ONE, Vec3::INFINITY, 3.0).is_none());
    assert!(w.sphere_trace(Vec3::Z * 10.0, Vec3::ZERO, -1.0).is_none());
    assert!(
        w.sphere_trace(Vec3::Z * 10.0, Vec3::ZERO, f32::NAN)
            .is_none()
    );
    // Starting inside the solid ground: a hit at distance 0.
    let hit = w
        .line_trace(Vec3::new(0.0, 0.0, -5.0), Vec3::new(0.0, 0.0, -50.0))
        .expect("inside");
    assert_eq!(hit.distance, 0.0);
    assert!(hit.normal.is_normalized());
    // A zero-length sphere sweep reports an overlap only.
    assert!(w.sphere_trace(Vec3::Z * 5.0, Vec3::Z * 5.0, 10.0).is_some());
    assert!(
        w.sphere_trace(Vec3::Z * 50.0, Vec3::Z * 50.0, 10.0)
            .is_none()
    );
}

#[test]
fn bad_shapes_are_errors_with_a_position() {
    let text = "(\n    shapes: [\n        Ground(height: 0.0),\n        Box(center: (0.0, 0.0, 0.0), half_extents: (1.0, -2.0, 1.0)),\n    ],\n)";
    let err = World::from_str(text).unwrap_err();
    let message = err.to_string();
    assert!(
        matches!(err, WorldError::Parse { line: 4, .. }),
        "{message}"
    );
    assert!(message.contains("half_extents"), "{message}");
    assert!(message.contains("hint:"), "{message}");

    let err = World::from_str("(shapes: [Ramp(start: (0.0, 0.0, 0.0), angle: 20.0, length: 1.0)])")
        .unwrap_err();
    assert!(err.to_string().contains("width"), "{err}");
    let err = World::from_str("(shapes: [Slab(height: 1.0)])").unwrap_err();
    assert!(err.to_string().contains("1:11"), "{err}");

    // Programmatic descriptions: try_from_desc reports, from_desc leaves the shape out.
    let desc = WorldDesc {
        shapes: vec![
            ShapeDesc::Ground { height: 0.0 },
            ShapeDesc::Heightfield {
                origin: (0.0, 0.0, 0.0),
                size: (10.0, 10.0),
                cells: (2, 2),
                heights: vec![1.0; 4],
                waves: vec![],
            },
        ],
    };
    assert!(matches!(
        World::try_from_desc(&desc),
        Err(WorldError::InvalidShape { index: 1, .. })
    ));
    let w = World::from_desc(&desc);
    assert_eq!(w.desc().shapes.len(), 1);
    assert!(World::load("/nonexistent/world.ron").is_err());
}

#[test]
fn sphere_traces_onto_the_ground_agree_with_parry3d() {
    // The world answers ball-versus-ground sweeps in closed form; parry3d's general cast is
    // the independent reference, on 2000 random sweeps (some start inside the ground, some
    // move away from it, some stop short of it).
    use parry3d::math::Pose;
    use parry3d::shape::HalfSpace;
    let height = 12.5;
    let w = world("(shapes: [Ground(height: 12.5)])");
    let ground = Pose::from_translation(Vec3::new(0.0, 0.0, height));
    let mut next = uniform(0x2545_f491);
    let mut hits = 0;
    for _ in 0..2000 {
        let start = Vec3::new(
            next() * 200.0 - 100.0,
            next() * 200.0 - 100.0,
            next() * 120.0 - 20.0,
        );
        let end = start
            + Vec3::new(
                next() * 60.0 - 30.0,
                next() * 60.0 - 30.0,
                next() * 200.0 - 150.0,
            );
        let radius = 0.5 + next() * 10.0;
        let ours = w.sphere_trace(start, end, radius);
        let delta = end - start;
        let length = delta.length();
        let reference = parry_ball_cast(start, end, radius, &ground, &HalfSpace::new(Vec3::Z));
        match (ours, reference) {
            (Some(hit), Some(r)) => {
                hits += 1;
                let distance = r.time_of_impact.max(0.0);
                assert!(near(hit.distance, distance, 1e-3), "{hit:?} vs {r:?}");
                assert_vec_near(hit.normal, Vec3::Z, 1e-5);
                // The touched point: one radius below the centre where the sweep stopped.
                let centre = start + delta / length * distance;
                assert_vec_near(hit.point, centre - Vec3::Z * radius, 1e-3);
            }
            (None, None) => {}
            (ours, reference) => panic!(
                "start {start} end {end} radius {radius}: ours {ours:?}, parry3d {reference:?}"
            ),
        }
    }
    assert!(
        hits > 500 && hits < 1900,
        "{hits} hits: the sweeps should mix hits and misses"
    );
}

#[test]
fn line_traces_onto_the_ground_agree_with_parry3d() {
    // The world answers rays against the ground in closed form; parry3d's ray cast on a
    // solid half-space is the independent reference, on 2000 random segments (some start
    // under the ground, some point up, some stop short of it, some run level).
    use parry3d::math::Pose;
    use parry3d::query::{Ray, RayCast};
    use parry3d::shape::HalfSpace;
    let height = -7.25;
    let w = world("(shapes: [Ground(height: -7.25)])");
    let ground = Pose::from_translation(Vec3::new(0.0, 0.0, height));
    let half_space = HalfSpace::new(Vec3::Z);
    let mut next = uniform(0x9e37_79b9);
    let (mut hits, mut inside) = (0, 0);
    for k in 0..2000 {
        let start = Vec3::new(
            next() * 200.0 - 100.0,
            next() * 200.0 - 100.0,
            next() * 120.0 - 30.0,
        );
        let mut delta = Vec3::new(
            next() * 60.0 - 30.0,
            next() * 60.0 - 30.0,
            next() * 200.0 - 150.0,
        );
        if k % 50 == 0 {
            delta.z = 0.0; // level: never reaches the plane from above
        }
        let end = start + delta;
        let length = delta.length();
        let ours = w.line_trace(start, end);
        let ray = Ray::new(start, delta / length);
        let reference = half_space.cast_ray_and_get_normal(&ground, &ray, length, true);
        match (ours, reference) {
            (Some(hit), Some(r)) => {
                hits += 1;
                assert!(
                    near(hit.distance, r.time_of_impact, 1e-3),
                    "{hit:?} vs {r:?}"
                );
                assert_vec_near(hit.point, start + ray.dir * r.time_of_impact, 1e-3);
                if r.time_of_impact == 0.0 {
                    // Starting in the solid: the normal faces back along the ray.
                    inside += 1;
                    assert_vec_near(hit.normal, -ray.dir, 1e-6);
                } else {
                    assert_vec_near(hit.normal, Vec3::Z, 1e-6);
                    assert!(near(hit.point.z, height, 1e-3), "{hit:?}");
                }
            }
            (None, None) => {}
            (ours, reference) => {
                panic!("start {start} end {end}: ours {ours:?}, parry3d {reference:?}")
            }
        }
    }
    assert!(
        hits > 300 && hits < 1900 && inside > 50,
        "{hits} hits, {inside} from inside: the segments should mix all cases"
    );
}

/// A small deterministic generator of floats in [0, 1) for the random sweeps.
/// A trace's answer as bits (point, normal, distance), to compare answers exactly.
fn hit_bits(hit: Option<strider_core::TraceHit>) -> Option<([u32; 3], [u32; 3], u32)> {
    hit.map(|h| {
        (
            h.point.to_array().map(f32::to_bits),
            h.normal.to_array().map(f32::to_bits),
            h.distance.to_bits(),
        )
    })
}

fn uniform(seed: u32) -> impl FnMut() -> f32 {
    let mut seed = seed;
    move || {
        seed = seed.wrapping_mul(1_664_525).wrapping_add(1_013_904_223);
        (seed >> 8) as f32 / (1u32 << 24) as f32
    }
}

/// parry3d's cast of a ball of `radius` from `start` to `end` against `shape` at `pose`,
/// stopping at a penetration: the independent reference for the world's sphere traces.
fn parry_ball_cast(
    start: Vec3,
    end: Vec3,
    radius: f32,
    pose: &parry3d::math::Pose,
    shape: &dyn parry3d::shape::Shape,
) -> Option<parry3d::query::ShapeCastHit> {
    use parry3d::math::Pose;
    use parry3d::query::{ShapeCastOptions, cast_shapes};
    use parry3d::shape::Ball;
    let delta = end - start;
    let length = delta.length();
    cast_shapes(
        &Pose::from_translation(start),
        delta / length,
        &Ball::new(radius),
        pose,
        Vec3::ZERO,
        shape,
        ShapeCastOptions {
            max_time_of_impact: length,
            target_distance: 0.0,
            stop_at_penetration: true,
            compute_impact_geometry_on_penetration: true,
        },
    )
    .expect("supported pair")
}

/// Compares the world's sphere traces with parry3d's cast of a ball against `reference`
/// (placed at `pose`) on `count` random sweeps from `start_box` (centre, half size) moved by
/// up to `reach`. Both must agree on hit or miss. parry3d's cast is iterative: it stops
/// when the ball is within a small gap of the shape, which on a grazing sweep can be
/// 0.15 cm of travel early; so it is held to "the ball is within 0.05 cm of touching where
/// parry3d stops". The world's answer is held to more, with parry3d's exact point
/// projection: where it says the ball stops, the centre is one radius (± 2e-4 cm) from the
/// shape, at 64 points before that it is not closer, and the touched point lies on the
/// shape, one radius from the centre against the normal (so the normal is the true one).
/// More than `min_hits` sweeps and fewer than 2800 must hit: a mix of hits and misses.
fn agree_with_parry(
    w: &World,
    reference: &dyn parry3d::shape::Shape,
    pose: &parry3d::math::Pose,
    (centre, half): (Vec3, Vec3),
    reach: Vec3,
    count: usize,
    seed: u32,
    min_hits: usize,
) {
    let mut next = uniform(seed);
    let mut hits = 0;
    for _ in 0..count {
        let mut r = || next() * 2.0 - 1.0;
        let start = centre + Vec3::new(r() * half.x, r() * half.y, r() * half.z);
        let end = start + Vec3::new(r() * reach.x, r() * reach.y, r() * reach.z);
        let radius = 0.5 + next() * 8.0;
        let ours = w.sphere_trace(start, end, radius);
        let delta = end - start;
        let length = delta.length();
        let cast = parry_ball_cast(start, end, radius, pose, reference);
        match (ours, cast) {
            (Some(hit), Some(r)) => {
                hits += 1;
                let context = format!("start {start} end {end} radius {radius}: {hit:?} vs {r:?}");
                let dir = delta / length;
                let gap = |t: f32| reference.distance_to_point(pose, start + dir * t, true);
                let parry_gap = gap(r.time_of_impact.max(0.0));
                assert!(
                    parry_gap <= radius + 0.05,
                    "{context}: parry3d {parry_gap} away"
                );
                if hit.distance > 0.0 {
                    let stop = gap(hit.distance);
                    assert!(near(stop, radius, 2e-4), "{context}: centre {stop} away");
                    for k in 0..64 {
                        let before = gap(hit.distance * k as f32 / 64.0);
                        assert!(before >= radius - 2e-4, "{context}: {before} away before");
                    }
                    let off = reference.distance_to_point(pose, hit.point, true);
                    assert!(off <= 2e-4, "{context}: touched point {off} off the shape");
                    let centre = start + dir * hit.distance;
                    assert_vec_near(hit.point, centre - hit.normal * radius, 1e-4);
                }
            }
            (None, None) => {}
            (ours, cast) => {
                panic!("start {start} end {end} radius {radius}: ours {ours:?}, parry3d {cast:?}")
            }
        }
    }
    assert!(
        hits > min_hits && hits < 2800,
        "{hits} hits: the sweeps should mix hits and misses"
    );
}

#[test]
fn sphere_traces_onto_boxes_agree_with_parry3d() {
    // The world answers ball-versus-box sweeps in closed form (faces, edges and corners);
    // parry3d's general cast is the independent reference. A box turned by 30° and tilted
    // by nothing (the world's boxes only turn about Z), swept at from every side, so the
    // sweeps meet faces, edges and corners, start touching it or miss it.
    use parry3d::math::Pose;
    use parry3d::shape::Cuboid;
    let w = world(
        "(shapes: [Box(center: (10.0, -20.0, 30.0), half_extents: (40.0, 15.0, 25.0), yaw: 30.0)])",
    );
    let pose = Pose::from_parts(
        Vec3::new(10.0, -20.0, 30.0),
        glam::Quat::from_rotation_z(30f32.to_radians()),
    );
    let cuboid = Cuboid::new(Vec3::new(40.0, 15.0, 25.0));
    agree_with_parry(
        &w,
        &cuboid,
        &pose,
        (Vec3::new(10.0, -20.0, 30.0), Vec3::splat(70.0)),
        Vec3::splat(90.0),
        3000,
        0x1234_5678,
        300,
    );
    // Sweeps aimed at a corner and along an edge, where the face test alone would be wrong:
    // a ball of 5 cm moving straight down 5 cm outside the box's +X face, past its top edge,
    // misses; one 3 cm outside touches the edge's cylinder where √(5² − 3²) = 4 cm above
    // the top.
    let w = world(
        "(shapes: [Box(center: (0.0, 0.0, 0.0), half_extents: (10.0, 10.0, 10.0), yaw: 0.0)])",
    );
    let down = |x: f32| w.sphere_trace(Vec3::new(x, 0.0, 40.0), Vec3::new(x, 0.0, -40.0), 5.0);
    assert!(down(15.5).is_none());
    let hit = down(13.0).expect("touches the top edge");
    assert!(near(hit.distance, 40.0 - 14.0, 1e-4), "{hit:?}");
    assert_vec_near(hit.normal, Vec3::new(0.6, 0.0, 0.8), 1e-5);
    assert_vec_near(hit.point, Vec3::new(10.0, 0.0, 10.0), 1e-4);
}

#[test]
fn sphere_traces_onto_a_ramp_agree_with_parry3d() {
    // Ball-versus-convex-hull sweeps in closed form (the ramp's faces as triangles, its
    // edges and corners) against parry3d's cast on a hull built here from the shared
    // corner formula; a 25° ramp turned by −40°, swept at from every side.
    use parry3d::math::Pose;
    use parry3d::shape::ConvexPolyhedron;
    let desc = ShapeDesc::Ramp {
        start: (20.0, -30.0, 4.0),
        yaw: -40.0,
        angle: 25.0,
        length: 120.0,
        width: 80.0,
    };
    let w = World::try_from_desc(&WorldDesc {
        shapes: vec![desc.clone()],
    })
    .expect("valid ramp");
    let corners = desc.ramp_corners().expect("a ramp");
    let hull = ConvexPolyhedron::from_convex_hull(&corners).expect("hull");
    let pose = Pose::from_parts(
        Vec3::new(20.0, -30.0, 4.0),
        glam::Quat::from_rotation_z((-40f32).to_radians()),
    );
    agree_with_parry(
        &w,
        &hull,
        &pose,
        (Vec3::new(20.0, -30.0, 40.0), Vec3::new(130.0, 130.0, 60.0)),
        Vec3::new(90.0, 90.0, 90.0),
        3000,
        0x5eed_0001,
        300,
    );
}

/// A world of one heightfield 200 × 160 cm from (−100, −80) at height 5, of `cells`, shaped
/// by `waves`, and the description's collision shapes (the reference's mesh).
fn heightfield_world(
    cells: (u32, u32),
    waves: Vec<Wave>,
) -> (
    World,
    Vec<(parry3d::math::Pose, parry3d::shape::SharedShape)>,
) {
    let desc = ShapeDesc::Heightfield {
        origin: (-100.0, -80.0, 5.0),
        size: (200.0, 160.0),
        cells,
        heights: vec![],
        waves,
    };
    let w = World::try_from_desc(&WorldDesc {
        shapes: vec![desc.clone()],
    })
    .expect("valid heightfield");
    (w, desc.collision_shapes().expect("a mesh"))
}

#[test]
fn sphere_traces_onto_a_heightfield_agree_with_parry3d() {
    // Ball-versus-triangle sweeps in closed form against the heightfield's triangles, and
    // parry3d's cast against the same mesh (the description's collision shape). The world
    // finds the triangles under a sweep by the grid's cells when it covers at most 64 of
    // them and through the mesh's tree otherwise: on 8 × 5 cells of 25 × 32 cm every sweep
    // here is read by cell; on 40 × 25 cells of 5 × 6.4 cm the long ones (up to 40 cm
    // across plus the ball) cover more than 64 and take the tree. Sweeps start up to 10 cm
    // outside the grid on every side.
    for (cells, seed) in [((8, 5), 0x0bad_cafe), ((40, 25), 0x0dd_ba11)] {
        let waves = vec![
            Wave {
                amplitude: 6.0,
                wavelength: 90.0,
                heading: 20.0,
                phase: 0.0,
            },
            Wave {
                amplitude: 3.0,
                wavelength: 45.0,
                heading: 110.0,
                phase: 40.0,
            },
        ];
        let (w, shapes) = heightfield_world(cells, waves);
        let (pose, mesh) = &shapes[0];
        agree_with_parry(
            &w,
            mesh.as_ref(),
            pose,
            (Vec3::new(0.0, 0.0, 30.0), Vec3::new(110.0, 90.0, 30.0)),
            Vec3::new(40.0, 40.0, 70.0),
            3000,
            seed,
            600,
        );
    }
}

#[test]
fn a_line_trace_ending_on_a_heightfield_hits_it() {
    // A flat heightfield 2 cm up (no waves, no heights), 4 × 4 cells of 25 cm: a segment
    // straight down that ends exactly on it hits at its whole length, as one ending on the
    // ground does; one that stops 1 cm short misses. Probes through a cell's inside, along
    // an edge between two cells and through a corner shared by six triangles all hit
    // (no crack between triangles), with the surface's normal +Z.
    let w = world(
        "(shapes: [Heightfield(origin: (-50.0, -50.0, 2.0), size: (100.0, 100.0), \
         cells: (4, 4), heights: [], waves: [])])",
    );
    for (x, y) in [(3.0, 7.0), (-25.0, 10.0), (0.0, 0.0), (25.0, -25.0)] {
        let top = Vec3::new(x, y, 10.0);
        let hit = w
            .line_trace(top, Vec3::new(x, y, 2.0))
            .unwrap_or_else(|| panic!("({x}, {y}): a miss"));
        assert_eq!(hit.distance, 8.0, "({x}, {y})");
        assert_eq!(hit.point, Vec3::new(x, y, 2.0), "({x}, {y})");
        assert_vec_near(hit.normal, Vec3::Z, 1e-6);
        assert!(
            w.line_trace(top, Vec3::new(x, y, 3.0)).is_none(),
            "({x}, {y})"
        );
    }
}

#[test]
fn line_traces_onto_a_heightfield_agree_with_parry3d() {
    // The world finds a heightfield's triangles under a line trace by the grid's cells
    // (when the segment covers at most 64 of them; the mesh's tree otherwise) and tests
    // each with parry3d's own ray-triangle test. parry3d's ray cast against the same mesh
    // (its tree, from the shape's description) is the reference: the same distance, bit
    // for bit, and the same normal turned to face the segment (to 1e-6: the world makes
    // it unit again). Segments straight down (a foot's probe), slanting, level, starting
    // under the ground, and long enough to take the tree, over a grid of 8 × 5 cells and a
    // fine one of 40 × 25, moved by the heightfield's origin.
    use parry3d::query::Ray;
    for (cells, seed) in [((8, 5), 0x0f00_d00d), ((40, 25), 0x0bee_f00d)] {
        let (w, shapes) = heightfield_world(cells, vec![field_wave()]);
        let (pose, mesh) = &shapes[0];
        let mut next = uniform(seed);
        let mut r = || next() * 2.0 - 1.0;
        let (mut hits, mut from_below) = (0, 0);
        for k in 0..3000 {
            let start = Vec3::new(r() * 110.0, r() * 90.0, 5.0 + r() * 30.0);
            let delta = match k % 4 {
                0 => Vec3::new(0.0, 0.0, -20.0 - r().abs() * 40.0),
                1 => Vec3::new(r() * 30.0, r() * 30.0, r() * 60.0),
                2 => Vec3::new(r() * 40.0, r() * 40.0, 0.0),
                _ => Vec3::new(r() * 150.0, r() * 150.0, r() * 40.0),
            };
            // The segment as the world computes it from its ends.
            let end = start + delta;
            let delta = end - start;
            let length = delta.length();
            let dir = delta / length;
            let ours = w.line_trace(start, end);
            let reference = mesh.cast_ray_and_get_normal(pose, &Ray::new(start, dir), length, true);
            let context = format!("start {start} end {end}: {ours:?} vs {reference:?}");
            match (ours, reference) {
                (Some(hit), Some(r)) => {
                    hits += 1;
                    assert_eq!(hit.distance, r.time_of_impact, "{context}");
                    let facing = if r.normal.dot(dir) > 0.0 {
                        -r.normal
                    } else {
                        r.normal
                    };
                    assert_vec_near(hit.normal, facing, 1e-6);
                    from_below += usize::from(hit.normal.z < 0.0);
                }
                (None, None) => {}
                _ => panic!("{context}"),
            }
        }
        assert!(
            hits > 500 && hits < 2800 && from_below > 20,
            "{hits} hits, {from_below} from below: the segments should mix all cases"
        );
    }
}

#[test]
fn the_shared_geometry_is_what_the_world_collides_with() {
    // Stairs turned by 90° (rising along −X): 3 steps of 20 × 40 cm and a 50 cm landing.
    let stairs = ShapeDesc::Stairs {
        start: (100.0, 0.0, 5.0),
        yaw: 90.0,
        width: 80.0,
        steps: 3,
        rise: 20.0,
        run: 40.0,
        landing: 50.0,
    };
    let boxes: Vec<_> = stairs.solid_boxes().collect();
    assert_eq!(boxes.len(), 3);
    // Step 1 (the second) spans 40..80 cm along −X from x = 100, rising to 5 + 40 cm.
    assert_vec_near(boxes[1].center, Vec3::new(40.0, 0.0, 25.0), 1e-4);
    assert_vec_near(boxes[1].half_extents, Vec3::new(40.0, 20.0, 20.0), 1e-6);
    // The last runs on through the landing: 80..170 cm.
    assert_vec_near(boxes[2].center, Vec3::new(-25.0, 0.0, 35.0), 1e-4);
    assert_vec_near(boxes[2].half_extents, Vec3::new(40.0, 45.0, 30.0), 1e-6);
    let field = ShapeDesc::Heightfield {
        origin: (-200.0, 300.0, 2.0),
        size: (400.0, 200.0),
        cells: (4, 2),
        heights: (0..15).map(|k| k as f32).collect(),
        waves: vec![field_wave()],
    };
    // Vertex (3, 1): x = −200 + 300, y = 300 + 100, z = 2 + heights[1 · 5 + 3] + waves.
    let v = field.heightfield_vertex(3, 1).expect("a heightfield");
    let z = 2.0 + 8.0 + wave_height(&[field_wave()], (-200.0, 300.0), 100.0, 400.0);
    assert_vec_near(v, Vec3::new(100.0, 400.0, z), 1e-4);
    assert!(stairs.heightfield_vertex(0, 0).is_none());
    // The world built from them collides with the tops they give.
    let w = World::from_desc(&WorldDesc {
        shapes: vec![stairs, field],
    });
    for b in &boxes {
        let top = b.center.z + b.half_extents.z;
        let (h, _) = w
            .ground_height(b.center.x, b.center.y, 500.0)
            .expect("a step");
        assert!(near(h, top, 1e-3), "{h} {top}");
    }
    let (h, _) = w.ground_height(v.x, v.y, 500.0).expect("the field");
    assert!(near(h, v.z, 1e-3), "{h} {}", v.z);
}

fn field_wave() -> Wave {
    Wave {
        amplitude: 3.0,
        wavelength: 150.0,
        heading: 30.0,
        phase: 10.0,
    }
}

#[test]
fn sphere_traces_in_a_batch_answer_as_each_alone() {
    // `sphere_traces` must give each query `sphere_trace`'s answer, bit for bit: a flat
    // world answers a batch 16 queries at a time, in columns, every other world one
    // query at a time. Queries from above and below the ground, moving up, down and
    // sideways, starting inside, touching it exactly at their end, missing short of it,
    // and off the common path (radius 0, −0, negative or NaN; spheres that do not move or
    // move about 1e-7 cm; NaN and infinite ends and radii; ends whose difference
    // overflows), in batches of 1 to 19. (The tilted plane's columns are checked in
    // `world.rs`'s own tests.)
    let queries = trace_cases();
    in_batches(
        &queries,
        |w, batch, hits| w.sphere_traces(batch, hits),
        |w, q| w.sphere_trace(q.start, q.end, q.radius),
    );
    // The same batches laid out in columns, as the VM asks.
    in_batches(
        &queries,
        |w, batch, hits| {
            in_columns(
                batch,
                hits,
                |traces, k, q| traces.set_sphere(k, *q),
                |traces, n, answers| w.sphere_traces_in_columns(traces, n, answers),
            );
        },
        |w, q| w.sphere_trace(q.start, q.end, q.radius),
    );
}

#[test]
fn line_traces_in_a_batch_answer_as_each_alone() {
    // `line_traces` must give each query `line_trace`'s answer, bit for bit, as
    // `sphere_traces` above: the same segments, and segments from whole centimetres
    // ending exactly on the ground (distance equal to the length), starting on it moving
    // down (distance 0) or up and sideways (a crossing at −0), starting below it, and
    // lying in it.
    let mut queries: Vec<LineQuery> = trace_cases()
        .iter()
        .map(|q| LineQuery {
            start: q.start,
            end: q.end,
        })
        .collect();
    let mut next = uniform(29);
    let mut r = || (next() * 2.0 - 1.0) * 100.0;
    for k in 0..200 {
        let at = Vec3::new(r(), r(), r()).round();
        let (start, end) = match k % 5 {
            0 => (
                Vec3::new(at.x, at.y, at.z.abs() + 1.0),
                Vec3::new(at.x, at.y, 0.0),
            ),
            1 => (
                Vec3::new(at.x, at.y, 0.0),
                Vec3::new(at.x + 3.0, at.y, -at.z.abs() - 1.0),
            ),
            2 => (
                Vec3::new(at.x, at.y, 0.0),
                Vec3::new(at.x - 2.0, at.y, at.z.abs() + 1.0),
            ),
            3 => (Vec3::new(at.x, at.y, -at.z.abs() - 1.0), at),
            _ => (Vec3::new(at.x, at.y, 0.0), Vec3::new(at.y, at.x + 1.0, 0.0)),
        };
        queries.push(LineQuery { start, end });
    }
    in_batches(
        &queries,
        |w, batch, hits| w.line_traces(batch, hits),
        |w, q| w.line_trace(q.start, q.end),
    );
    in_batches(
        &queries,
        |w, batch, hits| {
            in_columns(
                batch,
                hits,
                |traces, k, q| traces.set_line(k, *q),
                |traces, n, answers| {
                    w.line_traces_in_columns(traces, n, answers);
                },
            );
        },
        |w, q| w.line_trace(q.start, q.end),
    );
}

/// `queries` answered [`TRACE_COLUMNS`] at a time through a world's columns (`ask`), each
/// `put` into its column, into `hits`. The columns past the queries hold traces too, which
/// are not asked.
fn in_columns<Q>(
    queries: &[Q],
    hits: &mut [Option<TraceHit>],
    put: impl Fn(&mut TraceColumns, usize, &Q),
    ask: impl Fn(&TraceColumns, usize, &mut HitColumns),
) {
    for (queries, hits) in queries
        .chunks(TRACE_COLUMNS)
        .zip(hits.chunks_mut(TRACE_COLUMNS))
    {
        let mut traces = TraceColumns::default();
        let unasked = SphereQuery {
            start: Vec3::new(0.0, 0.0, 50.0),
            end: Vec3::new(0.0, 0.0, -50.0),
            radius: 2.0,
        };
        for k in 0..TRACE_COLUMNS {
            traces.set_sphere(k, unasked);
        }
        for (k, q) in queries.iter().enumerate() {
            put(&mut traces, k, q);
        }
        let mut answers = HitColumns::default();
        ask(&traces, queries.len(), &mut answers);
        for (k, hit) in hits.iter_mut().enumerate() {
            *hit = answers.get(k);
        }
    }
}

/// The queries of the batch trace tests: starts above and below a ground at 0 or −12.5,
/// moving up, down and sideways, starting inside, touching it exactly at their end,
/// missing short of it, and off the common path (radius 0, −0, negative or NaN; spheres
/// that do not move or move about 1e-7 cm; NaN and infinite ends and radii; ends whose
/// difference overflows).
fn trace_cases() -> Vec<SphereQuery> {
    let mut next = uniform(13);
    let mut r = || next() * 2.0 - 1.0;
    let mut queries = Vec::new();
    for k in 0..800 {
        let start = Vec3::new(r() * 300.0, r() * 300.0, r() * 60.0 + 20.0);
        let end = start + Vec3::new(r() * 80.0, r() * 80.0, r() * 120.0 - 30.0);
        let radius = 0.5 + (r() + 1.0) * 6.0;
        queries.push(match k % 16 {
            0 => SphereQuery {
                start,
                end: start,
                radius,
            },
            1 => SphereQuery {
                start,
                end,
                radius: 0.0,
            },
            2 => SphereQuery {
                start,
                end,
                radius: -1.0,
            },
            3 => SphereQuery {
                start: Vec3::new(f32::NAN, 0.0, 10.0),
                end,
                radius,
            },
            4 => SphereQuery {
                start,
                end: Vec3::new(0.0, f32::INFINITY, 0.0),
                radius,
            },
            5 => SphereQuery {
                start,
                end,
                radius: f32::INFINITY,
            },
            6 => SphereQuery {
                start,
                end: start + Vec3::Z * 1e-8,
                radius,
            },
            // Straight down from whole centimetres, the sphere (radius 4) ending just on the
            // ground at z = 0 or starting on or in it: distances equal to the length, and 0.
            7 => {
                let at = start.round();
                SphereQuery {
                    start: at,
                    end: Vec3::new(at.x, at.y, 4.0),
                    radius: 4.0,
                }
            }
            // Lengths about the 1e-7 below which a sphere counts as not moving, from a start
            // just above the origin (where steps of 1e-8 are exact enough to land there).
            8 => {
                let at = Vec3::new(0.0, 0.0, 0.001);
                let length = [0.5e-7, 1e-7, 1.5e-7, 3e-7][(k / 16) % 4];
                SphereQuery {
                    start: at,
                    end: at + Vec3::X * length,
                    radius,
                }
            }
            9 => SphereQuery {
                start,
                end,
                radius: f32::NAN,
            },
            10 => SphereQuery {
                start,
                end,
                radius: -0.0,
            },
            // Finite ends whose difference overflows.
            11 => SphereQuery {
                start: Vec3::new(-3e38, 0.0, 10.0),
                end: Vec3::new(3e38, 0.0, 10.0),
                radius,
            },
            _ => SphereQuery { start, end, radius },
        });
    }
    queries
}

/// Asks each world of the batch tests (flat grounds, answered in columns, and a ground
/// with a box, one query at a time) `queries` in batches of 1 to 19 through `batch`, and
/// checks every answer bit for bit against `alone`'s; at least 150 of them must hit.
fn in_batches<Q: std::fmt::Debug>(
    queries: &[Q],
    batch: impl Fn(&World, &[Q], &mut [Option<TraceHit>]),
    alone: impl Fn(&World, &Q) -> Option<TraceHit>,
) {
    let worlds = [
        "(shapes: [Ground(height: 0.0)])",
        "(shapes: [Ground(height: -12.5)])",
        "(shapes: [Ground(height: 0.0), Box(center: (0.0, 0.0, 10.0), half_extents: (50.0, 50.0, 10.0))])",
    ];
    for text in worlds {
        let w = world(text);
        let mut hits_seen = 0;
        let mut at = 0;
        for size in (1..20).cycle() {
            if at >= queries.len() {
                break;
            }
            let part = &queries[at..(at + size).min(queries.len())];
            let mut hits = vec![None; part.len()];
            batch(&w, part, &mut hits);
            for (q, hit) in part.iter().zip(&hits) {
                let alone = alone(&w, q);
                assert_eq!(
                    hit_bits(*hit),
                    hit_bits(alone),
                    "{text}: {q:?}: {hit:?} vs {alone:?}"
                );
                hits_seen += usize::from(hit.is_some());
            }
            at += size;
        }
        assert!(hits_seen > 150, "{text}: {hits_seen} hits");
    }
}
