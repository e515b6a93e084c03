//! Sphere traces against the shipped scenario worlds: `World::sphere_trace` (bounding-box
//! culling, closed-form ball sweeps) against parry3d's general cast of the same ball over
//! the same shapes (`ShapeDesc::collision_shapes`) — the baseline, measured in the same
//! run. 64 traces per iteration, each a 3 cm ball swept from 50 cm above the ground to
//! 50 cm below it at points spread over the scenario's walk, as a foot's landing grid
//! traces them.
//!
//! Run: `cargo bench --bench traces` (see docs/performance.md).

use criterion::{Criterion, criterion_group, criterion_main};
use glam::Vec3;
use parry3d::math::Pose;
use parry3d::query::{ShapeCastOptions, cast_shapes};
use parry3d::shape::{Ball, SharedShape};
use std::hint::black_box;
use strider::WorldQuery;
use strider::host::scenario::Scenario;
use strider::host::world::World;

/// Ball radius of the landing traces, cm.
const RADIUS: f32 = 3.0;

/// The nearest hit of a ball swept over every shape with parry3d's cast: the baseline.
fn parry_sweep(shapes: &[(Pose, SharedShape)], start: Vec3, end: Vec3) -> Option<f32> {
    let delta = end - start;
    let length = delta.length();
    let options = ShapeCastOptions {
        max_time_of_impact: length,
        target_distance: 0.0,
        stop_at_penetration: true,
        compute_impact_geometry_on_penetration: true,
    };
    let ball = Ball::new(RADIUS);
    shapes
        .iter()
        .filter_map(|(pose, shape)| {
            cast_shapes(
                &Pose::from_translation(start),
                delta / length,
                &ball,
                pose,
                Vec3::ZERO,
                shape.as_ref(),
                options,
            )
            .ok()
            .flatten()
            .map(|hit| hit.time_of_impact)
        })
        .min_by(f32::total_cmp)
}

fn traces(c: &mut Criterion) {
    for name in ["walk_flat", "slope", "stairs_up_down", "uneven_ground"] {
        let scenario = Scenario::load(format!("graphs/scenarios/{name}.ron"))
            .expect("a shipped scenario loads");
        let world = World::from_desc(&scenario.world);
        let shapes: Vec<_> = scenario
            .world
            .shapes
            .iter()
            .flat_map(|desc| desc.collision_shapes().expect("a shipped shape builds"))
            .collect();
        // 64 sweeps over the first 10 m along +Y, 0–35 cm to the side.
        let sweeps: Vec<(Vec3, Vec3)> = (0..64)
            .map(|i| {
                let (x, y) = ((i % 8) as f32 * 5.0, i as f32 * 15.0 + 3.0);
                let ground = world.ground_height(x, y, 500.0).map_or(0.0, |(z, _)| z);
                (
                    Vec3::new(x, y, ground + 50.0),
                    Vec3::new(x, y, ground - 50.0),
                )
            })
            .collect();
        let mut g = c.benchmark_group(format!("traces/{name}"));
        g.bench_function("world", |b| {
            b.iter(|| {
                for &(start, end) in &sweeps {
                    black_box(world.sphere_trace(black_box(start), black_box(end), RADIUS));
                }
            });
        });
        g.bench_function("parry3d_cast", |b| {
            b.iter(|| {
                for &(start, end) in &sweeps {
                    black_box(parry_sweep(&shapes, black_box(start), black_box(end)));
                }
            });
        });
        g.finish();
    }
}

criterion_group!(benches, traces);
criterion_main!(benches);
