//! `Instance::run_forward` performs no heap allocation once warmed up (docs/embedding.md:
//! "Once arrays and the debug buffer have reached their working size (after the first
//! frames), run_forward performs no heap allocation").
//!
//! The `strider` binary's counting global allocator is installed here too; it counts only
//! the allocations of the thread that asked, so allocations the test harness makes on other
//! threads (output capture, other tests) are not counted.

use std::path::Path;
use std::sync::{Arc, Mutex};
use strider_core::{EmptyWorld, Skeleton, Transform, Vec3};
use strider_nodes::Value;
use strider_vm::{FrameInput, InputPose, Instance, Program};

#[global_allocator]
static GLOBAL: strider_cli::CountingAllocator = strider_cli::CountingAllocator;

/// Tests in this file measure one at a time.
static SERIAL: Mutex<()> = Mutex::new(());

/// Heap allocations made by the current thread while running `f`.
fn allocations_in(f: impl FnOnce()) -> u64 {
    let ((), counted) = strider_cli::allocations_on_this_thread(f);
    counted.expect("the counting allocator is installed")
}

fn compile_file(path: &str) -> Arc<Program> {
    match strider_compiler::compile_file(Path::new(path)) {
        Ok(p) => Arc::new(p),
        Err(d) => panic!(
            "{path}:\n{}",
            d.iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join("\n")
        ),
    }
}

/// The mannequin skeleton every test here runs on.
fn mannequin() -> Arc<Skeleton> {
    strider_graph::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
        .unwrap_or_else(|_| panic!("mannequin loads"))
        .skeleton
}

fn instance(path: &str) -> Instance {
    Instance::new(compile_file(path), mannequin()).expect("instantiates")
}

/// Runs 10 warm-up frames, then counts the allocations of 100 more.
fn steady_state_allocations(inst: &mut Instance, debug: bool) -> u64 {
    let input = FrameInput {
        dt: 1.0 / 60.0,
        ..Default::default()
    };
    for _ in 0..10 {
        inst.run_forward(&input, &EmptyWorld, debug);
    }
    allocations_in(|| {
        for _ in 0..100 {
            inst.run_forward(&input, &EmptyWorld, debug);
        }
    })
}

#[test]
fn the_counter_sees_allocations_on_this_thread() {
    // The measuring harness itself must be able to fail: a Vec and a String are counted.
    let _guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let n = allocations_in(|| {
        let v: Vec<u64> = std::hint::black_box(Vec::with_capacity(16));
        let s = std::hint::black_box(String::from("allocates"));
        drop((v, s));
    });
    assert_eq!(n, 2);
    // And an array growing past its capacity inside a frame is seen too: a fresh instance
    // of the array graph, measured from its very first frame, allocates.
    let mut inst = instance("tests/graphs/arrays_every_frame.ron");
    let input = FrameInput {
        dt: 1.0 / 60.0,
        ..Default::default()
    };
    let first = allocations_in(|| inst.run_forward(&input, &EmptyWorld, true));
    assert!(
        first > 0,
        "the first frame grows arrays and the debug buffer"
    );
}

#[test]
fn pelvis_bob_frames_do_not_allocate() {
    let _guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    for debug in [false, true] {
        let mut inst = instance("graphs/pelvis_bob.ron");
        let n = steady_state_allocations(&mut inst, debug);
        assert_eq!(
            n, 0,
            "pelvis_bob, debug {debug}: {n} allocations in 100 frames"
        );
        // It did run: the pelvis is off its rest height at t = 110/60 s
        // (95 + 5·sin(660°) = 95 − 4.33).
        let pelvis = inst.pose().skeleton().find("pelvis").unwrap();
        let z = inst.pose_mut().global(pelvis).translation.z;
        assert!((z - 90.669873).abs() < 1e-2, "pelvis z {z}");
    }
}

#[test]
fn pelvis_bob_does_not_allocate_when_debug_is_toggled_or_tunables_change() {
    let _guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let mut inst = instance("graphs/pelvis_bob.ron");
    let amplitude = inst.program().variable_id("Amplitude").unwrap();
    let input = FrameInput {
        dt: 1.0 / 60.0,
        ..Default::default()
    };
    for k in 0..10 {
        inst.run_forward(&input, &EmptyWorld, k % 2 == 0);
    }
    let n = allocations_in(|| {
        for k in 0..100 {
            inst.set_float(amplitude, (k % 20) as f32);
            inst.run_forward(&input, &EmptyWorld, k % 2 == 0);
        }
    });
    assert_eq!(n, 0, "{n} allocations in 100 frames");
}

#[test]
fn array_heavy_frames_do_not_allocate_after_warm_up() {
    let _guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    for debug in [false, true] {
        let mut inst = instance("tests/graphs/arrays_every_frame.ron");
        // The array size cycles through 3..=9 (Frame mod 7 + 3); 10 warm-up frames reach 9.
        let n = steady_state_allocations(&mut inst, debug);
        assert_eq!(
            n, 0,
            "arrays_every_frame, debug {debug}: {n} allocations in 100 frames"
        );
        // It did run: after 110 frames Frame = 110, size = 110 mod 7 + 3 = 5 + 3 = 8, so the
        // points are (i, 2, i/2) for i = 0..7 and Longest = |(7, 2, 3.5)| = √(49 + 4 + 12.25)
        // = √65.25 = 8.0777472.
        let id = inst.program().variable_id("Frame").unwrap();
        assert_eq!(inst.variable(id), Value::Int(110));
        let id = inst.program().variable_id("Longest").unwrap();
        let Value::Float(longest) = inst.variable(id) else {
            panic!()
        };
        assert!((longest - 8.077_747).abs() < 1e-4, "Longest {longest}");
    }
}

#[test]
fn feet_finder_and_other_input_poses_do_not_allocate() {
    let _guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let mut inst = instance("graphs/examples/feet_finder.ron");
    assert_eq!(
        steady_state_allocations(&mut inst, true),
        0,
        "feet_finder, debug on"
    );

    // Previous and Locals input poses, and a component-to-world transform with NaN.
    let mut inst = instance("graphs/pelvis_bob.ron");
    let locals = inst.pose().locals().to_vec();
    let bad_world = Transform::from_translation(Vec3::new(f32::NAN, 0.0, 0.0));
    let inputs = [
        FrameInput {
            dt: 0.02,
            pose: InputPose::Previous,
            ..Default::default()
        },
        FrameInput {
            dt: f32::NAN,
            component_to_world: bad_world,
            pose: InputPose::Locals(&locals),
        },
    ];
    for k in 0..10 {
        inst.run_forward(&inputs[k % 2], &EmptyWorld, true);
    }
    let n = allocations_in(|| {
        for k in 0..100 {
            inst.run_forward(&inputs[k % 2], &EmptyWorld, true);
        }
    });
    assert_eq!(n, 0, "{n} allocations in 100 frames");
}

#[test]
fn batched_crowd_frames_do_not_allocate() {
    // `Instance::run_forward_batch` gathers each batch's members on the stack and orders
    // the crowd in scratch lists the thread keeps: 40 characters of two programs,
    // interleaved (batches of 16, 16 and 8), debug drawing on.
    let _guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let locomotion = compile_file("graphs/locomotion.ron");
    let bob = compile_file("graphs/pelvis_bob.ron");
    let skeleton = mannequin();
    let mut crowd: Vec<Instance> = (0..40)
        .map(|k| {
            let program = if k % 20 < 16 { &locomotion } else { &bob };
            Instance::new(Arc::clone(program), Arc::clone(&skeleton)).expect("instantiates")
        })
        .collect();
    let n = batched_allocations(&mut crowd, true, 50);
    assert_eq!(n, 0, "{n} allocations in 50 frames of 40 characters");
}

#[test]
fn a_worker_thread_that_reserved_its_batch_scratch_allocates_nothing_in_its_first_batch() {
    // A thread pool may give a worker its first share of a warmed-up crowd at any frame:
    // that worker's first batch makes the thread's scratch (the lanes, the IKs' chain
    // lanes, the crowd's order lists), unless `reserve_batch_scratch` made it before.
    let _guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    let locomotion = compile_file("graphs/locomotion.ron");
    let skeleton = mannequin();
    // One whole batch of a path and four more: every order list is used.
    let mut crowd: Vec<Instance> = (0..20)
        .map(|_| {
            Instance::new(Arc::clone(&locomotion), Arc::clone(&skeleton)).expect("instantiates")
        })
        .collect();
    let input = |_| FrameInput {
        dt: 1.0 / 60.0,
        ..Default::default()
    };
    // Warmed up on this thread: the instances' own buffers are at their working size.
    for _ in 0..10 {
        Instance::run_forward_batch(&mut crowd, input, &EmptyWorld, false);
    }
    let first_batch_on_a_new_thread = |crowd: &mut [Instance], reserve: bool| {
        std::thread::scope(|s| {
            s.spawn(|| {
                if reserve {
                    Instance::reserve_batch_scratch(&locomotion, crowd.len());
                }
                allocations_in(|| {
                    Instance::run_forward_batch(crowd, input, &EmptyWorld, false);
                })
            })
            .join()
            .expect("the worker runs")
        })
    };
    let unreserved = first_batch_on_a_new_thread(&mut crowd, false);
    assert!(
        unreserved > 0,
        "a new thread's first batch makes its scratch"
    );
    let reserved = first_batch_on_a_new_thread(&mut crowd, true);
    assert_eq!(reserved, 0, "{reserved} allocations after reserving");
}

/// Allocations in `frames` frames of `crowd` run in batches (`debug` as given), after 10
/// frames of warm-up; each character's time step one of 1/60 s, 1/30 s and 0.
fn batched_allocations(crowd: &mut [Instance], debug: bool, frames: usize) -> u64 {
    let input = |k: usize| FrameInput {
        dt: [1.0 / 60.0, 1.0 / 30.0, 0.0][k % 3],
        ..Default::default()
    };
    for _ in 0..10 {
        Instance::run_forward_batch(crowd, input, &EmptyWorld, debug);
    }
    allocations_in(|| {
        for _ in 0..frames {
            Instance::run_forward_batch(crowd, input, &EmptyWorld, debug);
        }
    })
}

/// With the `profile` feature and profiling on, frames still allocate nothing: the
/// per-instruction table is allocated with the instance.
#[cfg(feature = "profile")]
#[test]
fn profiled_frames_do_not_allocate() {
    let _guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    for path in ["graphs/pelvis_bob.ron", "graphs/foot_ik.ron"] {
        let mut inst = instance(path);
        inst.set_profiling(true);
        let n = steady_state_allocations(&mut inst, true);
        assert_eq!(n, 0, "{path}, profiling: {n} allocations in 100 frames");
        let runs: u64 = inst.profile().iter().map(|p| p.count).sum();
        assert!(runs > 0, "{path}: the frames were profiled");
        // Switching it off and resetting allocate nothing either.
        let n = allocations_in(|| {
            inst.reset_profile();
            inst.set_profiling(false);
            inst.run_forward(&FrameInput::default(), &EmptyWorld, false);
            inst.set_profiling(true);
            inst.run_forward(&FrameInput::default(), &EmptyWorld, false);
        });
        assert_eq!(n, 0, "{path}: toggling profiling allocated {n} times");
    }
    // Profiling instances batched together (the batch loop's profiled copy), on lanes.
    let locomotion = compile_file("graphs/locomotion.ron");
    let skeleton = mannequin();
    let mut crowd: Vec<Instance> = (0..6)
        .map(|_| {
            let mut i = Instance::new(Arc::clone(&locomotion), Arc::clone(&skeleton)).unwrap();
            i.set_profiling(true);
            i
        })
        .collect();
    let n = batched_allocations(&mut crowd, false, 20);
    assert_eq!(n, 0, "profiled batches: {n} allocations in 20 frames");
    assert!(
        crowd
            .iter()
            .all(|i| i.profile().iter().any(|p| p.nanos > 0))
    );
}

/// The locomotion graph walking a scenario (traces against the scenario's world, the
/// capsule moving, debug drawing on and off): once each foot has swung (arrays, such as a
/// spline's control points, and the debug buffer have reached their working size — the
/// first steps start about a second in), forward runs allocate nothing. Only `run_forward` is counted; the demo host's mover is not part of
/// the runtime.
#[test]
fn locomotion_frames_in_a_scenario_do_not_allocate() {
    let _guard = SERIAL.lock().unwrap_or_else(|e| e.into_inner());
    for scenario in ["walk_flat", "stairs_up_down", "strafe_8dir"] {
        let scenario =
            strider_host::scenario::Scenario::load(format!("graphs/scenarios/{scenario}.ron"))
                .unwrap();
        let mut sim = strider_host::scenario::Simulation::new(&scenario, 60);
        let mut inst = instance("graphs/locomotion.ron");
        let mut counted = 0;
        let mut allocations = 0;
        while let Some(frame) = sim.next_frame() {
            let input = FrameInput {
                dt: frame.dt,
                component_to_world: frame.component_to_world,
                pose: InputPose::Rest,
            };
            let debug = frame.index % 2 == 0;
            if frame.time < 3.0 {
                inst.run_forward(&input, sim.world(), debug);
            } else {
                allocations += allocations_in(|| inst.run_forward(&input, sim.world(), debug));
                counted += 1;
            }
        }
        assert!(counted > 300, "{}: {counted} frames", scenario.name);
        assert_eq!(
            allocations, 0,
            "{}: {allocations} allocations in {counted} frames",
            scenario.name
        );
    }
}
