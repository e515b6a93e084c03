//! `Instance::run_forward_batch` (docs/performance.md, "Batched execution") gives every
//! character exactly what `Instance::run_forward` gives it alone: poses, debug drawing and
//! graph variables bit-identical every frame, and every slot after a frame run with debug
//! (without it a batch leaves the slots of values that live only within a run as they
//! were), through scenarios where characters at different points of their walk take
//! different branches.

use std::path::Path;
use std::sync::Arc;
use strider::host::scenario::Scenario;
use strider::{EmptyWorld, FrameInput, Instance, Program, Skeleton};

mod common;

fn compile(graph: &str) -> Arc<Program> {
    Arc::new(strider::compile_file(Path::new(graph)).unwrap_or_else(|d| panic!("{graph}: {d:?}")))
}

fn mannequin() -> Arc<Skeleton> {
    strider::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
        .expect("skeleton")
        .skeleton
}

/// Whether two instances' output poses are bit-identical.
fn same_pose(a: &Instance, b: &Instance) -> bool {
    let (a, b) = (a.pose().locals(), b.pose().locals());
    a.len() == b.len() && a.iter().zip(b).all(|(x, y)| x.bit_eq(y))
}

/// Runs frame `f` of `batched` as one crowd and of `alone` one by one (`input(k)` for
/// character `k`, no world) and asserts that every character's pose is the same both ways.
fn run_both<'i>(
    batched: &mut [Instance],
    alone: &mut [Instance],
    input: impl Fn(usize) -> FrameInput<'i>,
    debug: bool,
    f: usize,
) {
    Instance::run_forward_batch(batched, &input, &EmptyWorld, debug);
    for (k, instance) in alone.iter_mut().enumerate() {
        instance.run_forward(&input(k), &EmptyWorld, debug);
    }
    for (k, (a, b)) in batched.iter().zip(alone.iter()).enumerate() {
        assert!(same_pose(a, b), "character {k} differs at frame {f}");
    }
}

/// Runs `characters` instances of `graph` through `scenario` at `hz`, character `k` offset
/// by `7 k` frames into it (so they are at different points of their cycles), `frames`
/// frames, once batched and once each alone, and compares them after every frame.
fn batched_equals_alone(graph: &str, scenario: &str, hz: u32, characters: usize, frames: usize) {
    let program = compile(graph);
    let skeleton = mannequin();
    let scenario = Scenario::load(scenario).expect("scenario");
    let (sim, track) = common::track(&scenario, hz);
    assert!(track.len() > 60, "{} frames", track.len());
    let make = || -> Vec<Instance> {
        (0..characters)
            .map(|_| Instance::new(Arc::clone(&program), Arc::clone(&skeleton)).unwrap())
            .collect()
    };
    let (mut batched, mut alone) = (make(), make());
    let what = format!("{graph} in {}", scenario.name);
    for f in 0..frames {
        let input = |k: usize| common::input_at(&track, f, 7 * k);
        // Debug on every other frame and on the last.
        let debug = f % 2 == 0 || f + 1 == frames;
        Instance::run_forward_batch(&mut batched, input, sim.world(), debug);
        for (k, instance) in alone.iter_mut().enumerate() {
            instance.run_forward(&input(k), sim.world(), debug);
        }
        for (k, (a, b)) in batched.iter().zip(&alone).enumerate() {
            common::assert_same_frame(&what, &program, k, f, a, b);
            // The path key too: batched on lanes, a jump the whole batch takes is folded
            // into every member's key at once, each member's own into its own.
            assert_eq!(
                a.path_key(),
                b.path_key(),
                "{what}: character {k}'s path key at frame {f}"
            );
            assert_eq!(
                a.jump_sites(),
                b.jump_sites(),
                "{what}: character {k}'s jump sites at frame {f}"
            );
        }
    }
    for (k, (a, b)) in batched.iter().zip(&alone).enumerate() {
        assert!(
            a.slots().bit_eq(b.slots()),
            "{what}: character {k}'s slots differ"
        );
    }
}

#[test]
fn a_batched_locomotion_crowd_walks_like_each_character_alone() {
    // 19 characters: one full batch of 16 and one of 3.
    batched_equals_alone(
        "graphs/locomotion.ron",
        "graphs/scenarios/start_stop.ron",
        60,
        19,
        150,
    );
    batched_equals_alone(
        "graphs/locomotion.ron",
        "graphs/scenarios/stairs_up_down.ron",
        30,
        19,
        90,
    );
    batched_equals_alone(
        "graphs/locomotion.ron",
        "graphs/scenarios/strafe_8dir.ron",
        144,
        17,
        150,
    );
}

#[test]
fn a_batched_foot_ik_crowd_stands_like_each_character_alone() {
    batched_equals_alone(
        "graphs/foot_ik.ron",
        "graphs/scenarios/uneven_ground.ron",
        60,
        18,
        120,
    );
}

#[test]
fn a_crowd_batches_tunables_set_by_the_host_like_each_character_alone() {
    // A batch of characters whose tunables are all the graph's defaults takes the values
    // no instruction writes from the program and keeps them in the thread's lanes for the
    // program's next batch; a batch with a character whose tunable the host set to another
    // value brings each character's own, and so does a batch after it or after another
    // program's. Five crowds take turns on this thread (batches of 16, picked by path):
    // locomotion, 48 characters, one with longer strides (`set_variable`; in the second
    // batch on the first frame, when every path key is equal and the crowd keeps its
    // order), so a batch after its batch must take the defaults again; locomotion
    // compiled with a shorter swing by default (the same slots, other values in them), 17;
    // locomotion with the defaults, 33 (the second batch keeps the first's); locomotion
    // with every character's swing shorter (the same value on all: `set_float`, and
    // `set_variable` on one), 17; and locomotion with one character's stride set and set
    // back to its default, 17. Each character must walk as it would alone, frame after
    // frame.
    use strider::nodes::Value;
    let locomotion = compile("graphs/locomotion.ron");
    let path = Path::new("graphs/locomotion.ron");
    let text = std::fs::read_to_string(path).expect("locomotion.ron");
    let swing_default = r#""SwingTime":                (type: Float, default: 0.5,"#;
    assert!(text.contains(swing_default), "SwingTime's default moved");
    let short_swing = strider::compiler::compile_str(
        path,
        &text.replace(swing_default, &swing_default.replace("0.5", "0.3")),
    )
    .map(Arc::new)
    .unwrap_or_else(|d| panic!("{d:?}"));
    let skeleton = mannequin();
    let scenario = Scenario::load("graphs/scenarios/start_stop.ron").expect("scenario");
    let (sim, track) = common::track(&scenario, 60);
    let stride = locomotion
        .variable_id("MaxFootStrideLength")
        .expect("stride");
    let swing = locomotion.variable_id("SwingTime").expect("swing");
    type Tuning = dyn Fn(usize, &mut Instance);
    let make = |program: &Arc<Program>, n: usize, tune: &Tuning| -> Vec<Instance> {
        (0..n)
            .map(|k| {
                let mut instance =
                    Instance::new(Arc::clone(program), Arc::clone(&skeleton)).unwrap();
                tune(k, &mut instance);
                instance
            })
            .collect()
    };
    let defaults = |_: usize, _: &mut Instance| {};
    let one_in_the_second_batch = move |k: usize, i: &mut Instance| {
        if k == 20 {
            i.set_variable(stride, &Value::Float(120.0)).unwrap();
        }
    };
    let every_swing = move |k: usize, i: &mut Instance| {
        if k == 5 {
            i.set_variable(swing, &Value::Float(0.3)).unwrap();
        } else {
            i.set_float(swing, 0.3);
        }
    };
    let set_back = move |k: usize, i: &mut Instance| {
        if k == 3 {
            i.set_float(stride, 120.0);
            i.set_float(stride, 70.0);
        }
    };
    let tunings: [(&Arc<Program>, usize, &Tuning); 5] = [
        (&locomotion, 48, &one_in_the_second_batch),
        (&short_swing, 17, &defaults),
        (&locomotion, 33, &defaults),
        (&locomotion, 17, &every_swing),
        (&locomotion, 17, &set_back),
    ];
    let mut crowds: Vec<(&Arc<Program>, Vec<Instance>, Vec<Instance>)> = tunings
        .iter()
        .map(|&(p, n, t)| (p, make(p, n, t), make(p, n, t)))
        .collect();
    for f in 0..60 {
        for (c, (program, batched, alone)) in crowds.iter_mut().enumerate() {
            let input = |k: usize| common::input_at(&track, f, 7 * k);
            Instance::run_forward_batch(batched, input, sim.world(), false);
            for (k, instance) in alone.iter_mut().enumerate() {
                instance.run_forward(&input(k), sim.world(), false);
            }
            for (k, (a, b)) in batched.iter().zip(alone.iter()).enumerate() {
                common::assert_same_frame(&format!("crowd {c}"), program, k, f, a, b);
            }
        }
    }
    // The tunings change how the crowds walk: the test compares different things.
    let pose = |crowd: &[Instance], k: usize| -> Vec<u32> {
        let locals = crowd[k].pose().locals();
        locals.iter().map(|t| t.translation.x.to_bits()).collect()
    };
    assert_ne!(
        pose(&crowds[2].1, 20),
        pose(&crowds[0].1, 20),
        "longer strides walk differently"
    );
    assert_ne!(
        pose(&crowds[2].1, 5),
        pose(&crowds[1].1, 5),
        "a shorter swing walks differently"
    );
    assert_eq!(
        pose(&crowds[1].1, 5),
        pose(&crowds[3].1, 5),
        "the same swing set by the host"
    );
}

#[test]
fn a_mixed_crowd_batches_each_program_and_refuses_none() {
    // Two programs interleaved (each instance's neighbours run the other), two instances
    // of one graph compiled twice (equal programs, different `Arc`s), and hazardous dts:
    // each must still run as it would alone.
    let bob = compile("graphs/pelvis_bob.ron");
    let bob_again = compile("graphs/pelvis_bob.ron");
    let ik = compile("graphs/foot_ik.ron");
    let skeleton = mannequin();
    let programs = [&bob, &bob, &ik, &bob, &ik, &ik, &bob_again, &bob, &bob];
    let make = || -> Vec<Instance> {
        programs
            .iter()
            .map(|p| Instance::new(Arc::clone(p), Arc::clone(&skeleton)).unwrap())
            .collect()
    };
    let (mut batched, mut alone) = (make(), make());
    let dts = [
        1.0 / 60.0,
        0.0,
        f32::NAN,
        1.0e9,
        -0.5,
        f32::INFINITY,
        1.0 / 30.0,
    ];
    for f in 0..40 {
        let input = |k: usize| FrameInput {
            dt: dts[(f + k) % dts.len()],
            ..FrameInput::default()
        };
        run_both(&mut batched, &mut alone, input, true, f);
        for (k, (a, b)) in batched.iter().zip(&alone).enumerate() {
            assert!(a.slots().bit_eq(b.slots()), "character {k} at frame {f}");
        }
    }
    // An empty crowd is a no-op.
    Instance::run_forward_batch(&mut [], |_| FrameInput::default(), &EmptyWorld, false);
}

#[test]
fn a_batch_solves_each_character_with_its_own_ik_axes() {
    // A batch prepares two-bone IK axes once for the characters that share them: characters
    // with axes of their own (a flipped primary axis, a tilted secondary axis, a longer
    // primary, none) between characters with the same ones must each still solve as they
    // would alone.
    use strider::nodes::Value;
    let program = compile("tests/graphs/ik_axes.ron");
    let skeleton = mannequin();
    let primary = program.variable_id("Primary").expect("Primary");
    let secondary = program.variable_id("Secondary").expect("Secondary");
    let axes = [
        ([-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([-1.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([-1.0, 0.0, 0.0], [0.0, 0.8, 0.6]),
        ([-1.0, 0.0, 0.0], [0.0, 0.8, 0.6]),
        ([-2.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
        ([0.0, 0.0, 0.0], [0.0, 1.0, 0.0]),
    ];
    let make = || -> Vec<Instance> {
        axes.iter()
            .map(|&(p, s)| {
                let mut instance =
                    Instance::new(Arc::clone(&program), Arc::clone(&skeleton)).unwrap();
                instance
                    .set_variable(primary, &Value::Vec3(p.into()))
                    .unwrap();
                instance
                    .set_variable(secondary, &Value::Vec3(s.into()))
                    .unwrap();
                instance
            })
            .collect()
    };
    let (mut batched, mut alone) = (make(), make());
    for f in 0..30 {
        let input = |_: usize| FrameInput {
            dt: 1.0 / 30.0,
            ..FrameInput::default()
        };
        run_both(&mut batched, &mut alone, input, false, f);
    }
    // The axes matter: characters 0, 2 and 4 end in different poses.
    let pose = |k: usize| batched[k].pose().locals().to_vec();
    let differ = |a: &[strider::core::Transform], b: &[strider::core::Transform]| {
        a.iter().zip(b).any(|(x, y)| !x.bit_eq(y))
    };
    assert!(differ(&pose(0), &pose(2)) && differ(&pose(0), &pose(4)));
}

/// A graph whose run jumps past a branch's body for the items of `Flags` equal to `Swap`
/// (its `JumpIfFalse` on `differs`): with `Swap` false the second item's, with it true
/// the first's. The same jumps, in another order.
const TWO_BRANCHES: &str = r#"
Graph(
    version: 1,
    name: "two_branches",
    variables: {
        "Flags": (type: BoolArray, default: [true, false]),
        "Swap":  (type: Bool, default: false, tunable: true),
        "Taken": (type: Int),
    },
    nodes: {
        "differs":    Xor(a: "flag", b: var("Swap")),
        "taken_next": Add(a: var("Taken"), b: 1),
    },
    events: {
        forward: [
            Set("Taken", 0),
            ForEach(items: var("Flags"), element: "flag", body: [
                Branch(condition: "differs", then: [ Set("Taken", "taken_next") ]),
            ]),
        ],
    },
)
"#;

#[test]
fn path_keys_name_the_jumps_in_their_order_alone_or_batched() {
    use strider::nodes::Value;
    let program = strider::compiler::compile_str(Path::new("two_branches.ron"), TWO_BRANCHES)
        .map(Arc::new)
        .unwrap_or_else(|d| panic!("{d:?}"));
    let swap = program.variable_id("Swap").expect("Swap");
    let taken = program.variable_id("Taken").expect("Taken");
    let skeleton = mannequin();
    // Instances 0, 2 and 4 keep `Swap` false; 1, 3 and 5 set it.
    let make = || -> Vec<Instance> {
        (0..6)
            .map(|k| {
                let mut instance =
                    Instance::new(Arc::clone(&program), Arc::clone(&skeleton)).unwrap();
                instance
                    .set_variable(swap, &Value::Bool(k % 2 == 1))
                    .expect("a bool");
                instance
            })
            .collect()
    };
    let (mut batched, mut alone) = (make(), make());
    for instance in &mut alone {
        instance.run_forward(&FrameInput::default(), &EmptyWorld, false);
    }
    // Both kinds take one of the two branches: the same jumps, in another order.
    for instance in &alone {
        assert_eq!(instance.variable(taken), Value::Int(1));
    }
    let (straight, swapped) = (alone[0].path_key(), alone[1].path_key());
    assert_ne!(straight, swapped, "the same jumps in another order");
    // The jump sites are a set: the same for both kinds, and not empty.
    let sites = alone[0].jump_sites();
    assert_ne!(sites, 0, "the runs jump");
    for (k, instance) in alone.iter().enumerate() {
        assert_eq!(
            instance.jump_sites(),
            sites,
            "instance {k}'s jump sites alone"
        );
    }
    for (k, instance) in alone.iter().enumerate() {
        let expected = if k % 2 == 0 { straight } else { swapped };
        assert_eq!(instance.path_key(), expected, "instance {k} alone");
    }
    // Batched: six instances are too few for a whole batch of one path, so every frame
    // runs them as one batch in crowd order, the two kinds parting at each branch; the
    // keys are the same as alone every time. (The locomotion crowds above compare keys on
    // lanes, where whole-batch jumps fold into every member's key at once.)
    for f in 0..2 {
        Instance::run_forward_batch(&mut batched, |_| FrameInput::default(), &EmptyWorld, false);
        for (k, (a, b)) in batched.iter().zip(&alone).enumerate() {
            assert_eq!(a.path_key(), b.path_key(), "instance {k}, frame {f}");
            assert_eq!(a.jump_sites(), b.jump_sites(), "instance {k}, frame {f}");
            assert_eq!(a.variable(taken), Value::Int(1), "instance {k}, frame {f}");
        }
    }
}
