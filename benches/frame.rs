//! One forward frame of the shipped graphs on the mannequin, in an empty world, at 60 Hz:
//! `Instance::run_forward` only (the instance is created and warmed up beforehand), and
//! `.../batch16`: 16 instances through `Instance::run_forward_batch` together (criterion's
//! throughput is per character, so its time per element compares with the single frame).
//!
//! `graphs/locomotion.ron` is benchmarked too when it exists and compiles (otherwise a note
//! is printed and it is skipped).
//!
//! Profiling overhead cannot be measured in one binary (the `profile` feature changes the
//! executor), so run this bench twice and compare (criterion reports the change against the
//! previous run of the same bench name):
//!
//! ```text
//! cargo bench --bench frame                             # feature not compiled in
//! cargo bench --bench frame --features strider-vm/profile   # compiled in, profiling off
//! cargo bench --bench frame --features profile          # also adds `.../profiling_on`
//! ```
//!
//! See docs/performance.md.

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use std::hint::black_box;
use std::path::Path;
use std::sync::Arc;
use strider::core::Skeleton;
use strider::{EmptyWorld, FrameInput, Instance, Program};

const GRAPHS: [&str; 3] = [
    "graphs/foot_ik.ron",
    "graphs/pelvis_bob.ron",
    "graphs/locomotion.ron",
];

fn mannequin() -> Arc<Skeleton> {
    strider::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
        .expect("graphs/skeletons/mannequin.ron loads")
        .skeleton
}

/// The compiled graph at `path`, or `None` (with a note) when it is missing or does not
/// compile yet.
fn program(path: &str) -> Option<Arc<Program>> {
    if !Path::new(path).exists() {
        eprintln!("note: {path} does not exist; skipped");
        return None;
    }
    match strider::compile_file(Path::new(path)) {
        Ok(p) => Some(Arc::new(p)),
        Err(d) => {
            eprintln!(
                "note: {path} does not compile ({} diagnostics, first: {}); skipped",
                d.len(),
                d[0]
            );
            None
        }
    }
}

/// A 60 Hz frame from the rest pose at the origin.
fn input() -> FrameInput<'static> {
    FrameInput {
        dt: 1.0 / 60.0,
        ..Default::default()
    }
}

/// An instance of `program` on `skeleton`, after 60 warm-up frames (arrays and debug
/// buffers at their working size, smoothing state settled).
fn warm_instance(program: &Arc<Program>, skeleton: &Arc<Skeleton>) -> Option<Instance> {
    match Instance::new(Arc::clone(program), Arc::clone(skeleton)) {
        Ok(mut inst) => {
            for _ in 0..60 {
                inst.run_forward(&input(), &EmptyWorld, false);
            }
            Some(inst)
        }
        Err(e) => {
            eprintln!(
                "note: {} does not instantiate: {e}; skipped",
                program.name()
            );
            None
        }
    }
}

fn frames(c: &mut Criterion) {
    let skeleton = mannequin();
    let mut g = c.benchmark_group("frame");
    for path in GRAPHS {
        let Some(program) = program(path) else {
            continue;
        };
        let Some(mut inst) = warm_instance(&program, &skeleton) else {
            continue;
        };
        let name = Path::new(path)
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default();
        let frame = input();
        g.throughput(Throughput::Elements(1));
        g.bench_function(name.as_str(), |b| {
            b.iter(|| inst.run_forward(black_box(&frame), &EmptyWorld, false));
        });
        let mut crowd: Vec<Instance> = (0..16)
            .filter_map(|_| warm_instance(&program, &skeleton))
            .collect();
        g.throughput(Throughput::Elements(crowd.len() as u64));
        g.bench_function(format!("{name}/batch16"), |b| {
            b.iter(|| {
                Instance::run_forward_batch(&mut crowd, |_| black_box(input()), &EmptyWorld, false);
            });
        });
        g.throughput(Throughput::Elements(1));
        #[cfg(feature = "profile")]
        {
            inst.set_profiling(true);
            g.bench_function(format!("{name}/profiling_on"), |b| {
                b.iter(|| inst.run_forward(black_box(&frame), &EmptyWorld, false));
            });
            inst.set_profiling(false);
        }
    }
    g.finish();
}

criterion_group!(benches, frames);
criterion_main!(benches);
