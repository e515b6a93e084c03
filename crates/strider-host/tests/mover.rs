//! The kinematic mover: acceleration, stairs, walls, falls, degenerate dt, determinism.

use glam::{Vec2, Vec3};
use strider_host::mover::{Facing, MoveInput, Mover, MoverSettings};
use strider_host::world::World;

const H: f32 = 1.0 / 720.0;

fn world(text: &str) -> World {
    World::from_str(text).unwrap_or_else(|e| panic!("{e}"))
}

fn walk(direction: Vec2, speed: f32) -> MoveInput {
    MoveInput {
        direction,
        speed,
        facing: Facing::Velocity,
    }
}

fn flat() -> World {
    world("(shapes: [Ground(height: 0.0)])")
}

#[test]
fn reaches_the_commanded_speed_in_the_acceleration_time() {
    let w = flat();
    let settings = MoverSettings::default();
    let mut m = Mover::new(settings, Vec3::ZERO, 0.0);
    // Settle on the floor.
    m.step(&MoveInput::STAND, H, &w);
    assert!(m.is_grounded());
    let input = walk(Vec2::Y, 150.0);
    // 150 / 1200 = 0.125 s = 90 steps of 1/720 s.
    let steps = (150.0 / settings.acceleration / H).round() as usize;
    assert_eq!(steps, 90);
    for i in 0..steps {
        m.step(&input, H, &w);
        if i == steps / 2 - 1 {
            let v = m.velocity().length();
            assert!((v - 75.0).abs() < 0.01, "half-way speed {v}");
        }
    }
    let v = m.velocity();
    assert!(
        (v.y - 150.0).abs() < 0.01 && v.x.abs() < 1e-4 && v.z == 0.0,
        "{v}"
    );
    // Distance covered while accelerating: v² / 2a = 9.375 cm (discretised: + v·h/2).
    let expected = 150.0 * 150.0 / (2.0 * settings.acceleration) + 150.0 * H / 2.0;
    assert!(
        (m.position().y - expected).abs() < 0.01,
        "{}",
        m.position().y
    );
    assert_eq!(m.position().z, 0.0);

    // Braking to rest: 150 / 1600 s.
    let brake_steps = (150.0 / settings.braking / H).ceil() as usize;
    for _ in 0..brake_steps {
        m.step(&MoveInput::STAND, H, &w);
    }
    assert!(m.velocity().length() < 1e-3, "{}", m.velocity());
}

#[test]
fn turns_at_the_turn_rate_and_faces_the_velocity() {
    let w = flat();
    let mut m = Mover::new(MoverSettings::default(), Vec3::ZERO, 0.0);
    // Strafe right (−X... yaw 90 faces −X) while looking at yaw 90.
    let look = MoveInput {
        direction: Vec2::X,
        speed: 150.0,
        facing: Facing::Look(90.0),
    };
    // 90° at 540°/s = 1/6 s = 120 steps.
    for _ in 0..60 {
        m.step(&look, H, &w);
    }
    assert!((m.yaw() - 45.0).abs() < 1e-3, "{}", m.yaw());
    for _ in 0..60 {
        m.step(&look, H, &w);
    }
    assert!((m.yaw() - 90.0).abs() < 1e-3, "{}", m.yaw());
    // Velocity facing: walking along +X turns to yaw −90 (Rz(−90°) maps +Y to +X).
    for _ in 0..720 {
        m.step(&walk(Vec2::X, 150.0), H, &w);
    }
    assert!((m.yaw() + 90.0).abs() < 1e-3, "{}", m.yaw());
    let forward = m.component_to_world().transform_vector(Vec3::Y);
    assert!((forward - Vec3::X).length() < 1e-5, "{forward}");
    let t = m.component_to_world();
    assert_eq!(t.translation, m.position());
}

#[test]
fn climbs_stairs_and_comes_down_again() {
    let w = world(
        "(shapes: [Ground(height: 0.0), \
          Stairs(start: (0.0, 100.0, 0.0), yaw: 0.0, width: 200.0, steps: 8, rise: 15.0, run: 30.0, landing: 150.0), \
          Stairs(start: (0.0, 640.0, 0.0), yaw: 180.0, width: 200.0, steps: 8, rise: 15.0, run: 30.0)])",
    );
    let mut m = Mover::new(MoverSettings::default(), Vec3::ZERO, 0.0);
    let input = walk(Vec2::Y, 150.0);
    let mut top_reached = false;
    let mut max_z = 0f32;
    for _ in 0..(720.0 * 2.9) as usize {
        m.step(&input, H, &w);
        max_z = max_z.max(m.position().z);
    }
    // After 2.9 s at 150 cm/s the capsule is on the landing (y ≈ 420).
    let p = m.position();
    assert!(p.y > 340.0 && p.y < 490.0, "{p}");
    assert!((p.z - 120.0).abs() < 2.0, "on the landing: {p}");
    assert!(m.is_grounded());
    for _ in 0..720 * 3 {
        m.step(&input, H, &w);
        if (m.position().z - 120.0).abs() < 0.5 {
            top_reached = true;
        }
        // Going down it stays on the steps (snapped), never falls.
        assert!(m.is_grounded(), "airborne at {}", m.position());
        max_z = max_z.max(m.position().z);
    }
    assert!(top_reached);
    assert!(max_z <= 120.0 + 1e-3);
    let p = m.position();
    assert!(p.y > 700.0 && p.z.abs() < 1e-3, "back on the ground: {p}");
}

#[test]
fn steps_higher_than_the_step_height_block() {
    let w = world(
        "(shapes: [Ground(height: 0.0), Box(center: (0.0, 200.0, 30.0), half_extents: (300.0, 50.0, 30.0))])",
    );
    let mut m = Mover::new(MoverSettings::default(), Vec3::ZERO, 0.0);
    for _ in 0..720 * 3 {
        m.step(&walk(Vec2::Y, 150.0), H, &w);
    }
    // The box (top 60 cm, front face at y = 150) is higher than a step: the lifted
    // capsule's bottom hemisphere (centre 45 + 34 = 79 cm up, radius 34) rests against its
    // top edge, sqrt(34² − 19²) in front of the face.
    let p = m.position();
    let gap = (34.0f32 * 34.0 - 19.0 * 19.0).sqrt();
    assert!(p.z.abs() < 1e-3 && (p.y - (150.0 - gap)).abs() < 0.2, "{p}");
}

#[test]
fn walks_up_and_down_a_ramp_on_its_surface() {
    let w = world(
        "(shapes: [Ground(height: 0.0), \
          Ramp(start: (0.0, 100.0, 0.0), yaw: 0.0, angle: 20.0, length: 300.0, width: 200.0), \
          Platform(center: (0.0, 500.0), half_size: (100.0, 100.0), top: 109.19253), \
          Ramp(start: (0.0, 900.0, 0.0), yaw: 180.0, angle: 20.0, length: 300.0, width: 200.0)])",
    );
    let tan = 20f32.to_radians().tan();
    let mut m = Mover::new(MoverSettings::default(), Vec3::ZERO, 0.0);
    for _ in 0..720 * 8 {
        m.step(&walk(Vec2::Y, 150.0), H, &w);
        let p = m.position();
        assert!(m.is_grounded(), "{p}");
        // On the slope (away from its ends) the feet are on the surface under the axis.
        if p.y > 140.0 && p.y < 360.0 {
            assert!((p.z - (p.y - 100.0) * tan).abs() < 0.05, "{p}");
        }
        if p.y > 640.0 && p.y < 860.0 {
            assert!((p.z - (900.0 - p.y) * tan).abs() < 0.05, "{p}");
        }
    }
    assert!(m.position().y > 1000.0);
}

#[test]
fn slides_along_a_wall_without_penetrating() {
    // A wall whose −Y face is the plane y = 200.
    let w = world(
        "(shapes: [Ground(height: 0.0), Box(center: (0.0, 250.0, 150.0), half_extents: (2000.0, 50.0, 150.0))])",
    );
    let radius = MoverSettings::default().radius;
    let mut m = Mover::new(MoverSettings::default(), Vec3::ZERO, 0.0);
    let input = walk(Vec2::new(1.0, 1.0).normalize(), 300.0);
    for _ in 0..720 * 4 {
        m.step(&input, H, &w);
        assert!(m.position().y <= 200.0 - radius + 0.01, "{}", m.position());
    }
    let p = m.position();
    assert!(
        (p.y - (200.0 - radius)).abs() < 0.2,
        "against the wall: {p}"
    );
    // Sliding keeps the tangential part of the velocity: 300 · cos 45° along X.
    assert!(
        (m.velocity().x - 300.0 * 0.5f32.sqrt()).abs() < 1.0,
        "{}",
        m.velocity()
    );
    assert!(p.x > 600.0, "{p}");
}

#[test]
fn falls_from_a_height_in_sqrt_2h_over_g() {
    let w = flat();
    let settings = MoverSettings::default();
    let h = 200.0;
    let mut m = Mover::new(settings, Vec3::new(0.0, 0.0, h), 0.0);
    let mut t = 0.0f64;
    while !m.is_grounded() && t < 5.0 {
        m.step(&MoveInput::STAND, H, &w);
        t += f64::from(H);
    }
    let expected = (2.0 * h / settings.gravity).sqrt() as f64; // 0.639 s
    assert!(
        (t - expected).abs() < 0.005,
        "landed after {t} s, expected {expected}"
    );
    assert_eq!(m.position().z, 0.0);
    assert_eq!(m.velocity().z, 0.0);
}

#[test]
fn walking_off_a_platform_edge_falls_and_lands() {
    let w = world(
        "(shapes: [Ground(height: 0.0), Platform(center: (0.0, 0.0), half_size: (200.0, 200.0), top: 200.0)])",
    );
    let settings = MoverSettings::default();
    let mut m = Mover::new(settings, Vec3::new(0.0, 100.0, 200.0), 0.0);
    let input = walk(Vec2::Y, 150.0);
    let mut left_at: Option<(f64, f32)> = None;
    let mut landed_at = None;
    let mut t = 0.0f64;
    for _ in 0..720 * 4 {
        let was = m.is_grounded();
        m.step(&input, H, &w);
        t += f64::from(H);
        if was && !m.is_grounded() && left_at.is_none() {
            left_at = Some((t, m.position().z));
        }
        if !was && m.is_grounded() && left_at.is_some() && landed_at.is_none() {
            landed_at = Some(t);
        }
    }
    let (t0, z0) = left_at.expect("walked off");
    let t1 = landed_at.expect("landed");
    // It leaves grounded with no vertical speed from height z0.
    let expected = f64::from((2.0 * z0 / settings.gravity).sqrt());
    assert!(z0 > 150.0 && z0 <= 200.0, "{z0}");
    assert!(
        ((t1 - t0) - expected).abs() < 0.01,
        "fell {} s, expected {expected}",
        t1 - t0
    );
    assert_eq!(m.position().z, 0.0);
    assert!(m.position().y > 200.0);
}

#[test]
fn walking_into_the_void_falls_forever_without_nan() {
    let w = world("(shapes: [Platform(center: (0.0, 0.0), half_size: (100.0, 100.0), top: 0.0)])");
    let mut m = Mover::new(MoverSettings::default(), Vec3::ZERO, 0.0);
    for _ in 0..720 * 10 {
        m.step(&walk(Vec2::Y, 300.0), H, &w);
    }
    assert!(!m.is_grounded());
    assert!(m.position().is_finite() && m.position().z < -10_000.0);
    assert!(m.velocity().z >= -MoverSettings::default().max_fall_speed);
}

#[test]
fn zero_and_huge_dt_stay_finite() {
    let w = world(
        "(shapes: [Ground(height: 0.0), Stairs(start: (0.0, 100.0, 0.0), width: 200.0, steps: 8, rise: 15.0, run: 30.0)])",
    );
    let mut m = Mover::new(MoverSettings::default(), Vec3::ZERO, 0.0);
    let input = walk(Vec2::Y, 400.0);
    m.step(&input, 1.0 / 60.0, &w);
    let before = (m.position(), m.velocity(), m.yaw());
    for _ in 0..3 {
        m.step(&input, 0.0, &w);
    }
    assert_eq!(before, (m.position(), m.velocity(), m.yaw()));
    m.step(&input, 1.0, &w);
    assert!(m.position().is_finite() && m.velocity().is_finite() && m.yaw().is_finite());
    assert!(
        m.position().z > 100.0,
        "climbed during the hitch: {}",
        m.position()
    );
    for dt in [f32::NAN, f32::INFINITY, -1.0, 1.0e9] {
        m.step(&input, dt, &w);
        assert!(m.component_to_world().is_finite(), "dt {dt}");
    }
    let weird = MoveInput {
        direction: Vec2::new(f32::NAN, 1.0),
        speed: f32::INFINITY,
        facing: Facing::Look(f32::NAN),
    };
    m.step(&weird, 0.1, &w);
    assert!(m.component_to_world().is_finite());
    let broken = MoverSettings {
        radius: f32::NAN,
        gravity: -5.0,
        max_substep: 0.0,
        ..MoverSettings::default()
    };
    assert!(broken.validate().is_err());
    let mut m = Mover::new(broken, Vec3::NAN, f32::NAN);
    m.step(&input, 1.0, &w);
    assert!(m.component_to_world().is_finite());
}

fn run_path(w: &World) -> Vec<(Vec3, Vec3, f32)> {
    let mut m = Mover::new(MoverSettings::default(), Vec3::new(0.0, -50.0, 0.0), 10.0);
    let mut path = Vec::new();
    for i in 0..720 * 6 {
        let angle = i as f32 * 0.0003;
        let input = MoveInput {
            direction: Vec2::new(angle.sin(), angle.cos()),
            speed: if i % 1500 < 1200 { 320.0 } else { 0.0 },
            facing: if i < 2000 {
                Facing::Velocity
            } else {
                Facing::Look(30.0)
            },
        };
        m.step(&input, H, w);
        path.push((m.position(), m.velocity(), m.yaw()));
    }
    path
}

#[test]
fn same_inputs_give_a_bit_identical_path() {
    let w = world(
        "(shapes: [Ground(height: 0.0), \
          Stairs(start: (0.0, 100.0, 0.0), width: 300.0, steps: 6, rise: 18.0, run: 28.0, landing: 80.0), \
          Box(center: (250.0, 500.0, 100.0), half_extents: (40.0, 300.0, 100.0), yaw: 15.0), \
          Heightfield(origin: (-2000.0, 700.0, 0.0), size: (4000.0, 2000.0), cells: (80, 40), \
                      waves: [(amplitude: 4.0, wavelength: 300.0, heading: 20.0)])])",
    );
    let a = run_path(&w);
    let b = run_path(&w);
    assert!(a == b);
    let last = a.last().unwrap();
    assert!(last.0.is_finite() && last.0.y > 300.0, "{:?}", last);
}

#[test]
fn one_step_of_dt_equals_the_same_substeps() {
    // step(dt) splits into equal sub-steps: 1/60 s with max_substep 1/60 is one sub-step,
    // 1/30 s is two of 1/60 s.
    let w = flat();
    let input = walk(Vec2::new(0.3, 0.8), 250.0);
    let mut a = Mover::new(MoverSettings::default(), Vec3::ZERO, 0.0);
    let mut b = a.clone();
    for _ in 0..30 {
        a.step(&input, 1.0 / 30.0, &w);
        b.step(&input, 1.0 / 60.0, &w);
        b.step(&input, 1.0 / 60.0, &w);
    }
    assert_eq!(a.position(), b.position());
    assert_eq!(a.velocity(), b.velocity());
}
