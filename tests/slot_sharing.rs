//! Slot sharing (`strider_compiler::Options::keep_pin_values` off, the default): values
//! that never outlive a run share slots, and the shipped graphs run exactly as they do
//! with a slot per value.

use std::path::Path;
use std::sync::Arc;
use strider::compiler::{Options, compile_with};
use strider::host::scenario::{Scenario, Simulation};
use strider::nodes::Op;
use strider::{FrameInput, InputPose, Instance, Program};

fn compile(graph: &str, keep_pin_values: bool) -> Program {
    let loaded = strider::graph::load_graph(Path::new(graph)).expect("loads");
    compile_with(&loaded, Options { keep_pin_values }).unwrap_or_else(|d| panic!("{graph}: {d:?}"))
}

fn compile_str(text: &str, keep_pin_values: bool) -> Program {
    let loaded =
        strider::graph::load_graph_str(Path::new("test.ron"), text.to_string()).expect("loads");
    compile_with(&loaded, Options { keep_pin_values }).unwrap_or_else(|d| panic!("{d:?}"))
}

/// Scalar slots of an instance of `program`: bools, ints, floats, vectors, rotations,
/// transforms.
fn scalar_slots(program: &Program) -> [usize; 6] {
    let s = program.initial_slots();
    [
        s.bools.len(),
        s.ints.len(),
        s.floats.len(),
        s.vec3s.len(),
        s.quats.len(),
        s.transforms.len(),
    ]
}

/// Runs `graph` compiled both ways side by side through `scenario` at `hz` and asserts
/// that every frame's pose and every variable are bit-identical.
fn same_through(graph: &str, scenario: &str, hz: u32) {
    let (kept, shared) = (
        Arc::new(compile(graph, true)),
        Arc::new(compile(graph, false)),
    );
    let skeleton = strider::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
        .expect("skeleton")
        .skeleton;
    let mut a = Instance::new(Arc::clone(&kept), Arc::clone(&skeleton)).unwrap();
    let mut b = Instance::new(Arc::clone(&shared), skeleton).unwrap();
    let scenario = Scenario::load(scenario).expect("scenario");
    let mut sim = Simulation::new(&scenario, hz);
    let mut frames = 0;
    while let Some(frame) = sim.next_frame() {
        let input = FrameInput {
            dt: frame.dt,
            component_to_world: frame.component_to_world,
            pose: InputPose::Rest,
        };
        a.run_forward(&input, sim.world(), false);
        b.run_forward(&input, sim.world(), false);
        let (x, y) = (a.pose().locals(), b.pose().locals());
        assert!(
            x.len() == y.len() && x.iter().zip(y).all(|(p, q)| p.bit_eq(q)),
            "{graph} in {} at {hz} Hz: poses differ at frame {frames}",
            scenario.name
        );
        frames += 1;
    }
    for (i, v) in kept.variables().iter().enumerate() {
        let id = strider::vm::VariableId(i as u32);
        assert_eq!(
            format!("{:?}", a.variable(id)),
            format!("{:?}", b.variable(id)),
            "{graph}: variable {}",
            v.name
        );
    }
    assert!(frames > 100, "{frames} frames");
}

#[test]
fn the_locomotion_graph_runs_the_same_with_shared_slots() {
    for scenario in [
        "walk_flat",
        "strafe_8dir",
        "stairs_up_down",
        "uneven_ground",
        "hitch",
        "void",
    ] {
        same_through(
            "graphs/locomotion.ron",
            &format!("graphs/scenarios/{scenario}.ron"),
            60,
        );
    }
    same_through("graphs/locomotion.ron", "graphs/scenarios/reverse.ron", 144);
    same_through(
        "graphs/foot_ik.ron",
        "graphs/scenarios/standing_on_stairs.ron",
        60,
    );
}

#[test]
fn shared_slots_shrink_the_shipped_graphs() {
    for graph in ["graphs/locomotion.ron", "graphs/foot_ik.ron"] {
        let (kept, shared) = (compile(graph, true), compile(graph, false));
        let (k, s) = (scalar_slots(&kept), scalar_slots(&shared));
        // Floats, vectors and transforms: most are node outputs read once, soon after.
        for t in [2, 3, 5] {
            assert!(
                2 * s[t] < k[t],
                "{graph}: {s:?} shared slots against {k:?} kept"
            );
        }
        // The same instructions, reading other slots, less the copies that went; a fused
        // instruction (the shared build's superinstructions) counts as its two ops.
        let ops = |p: &Program, copies: bool| -> Vec<Op> {
            p.code()
                .iter()
                .flat_map(|i| match i.op.fused_parts() {
                    Some((first, second)) => vec![first, second],
                    None => vec![i.op],
                })
                .filter(|op| copies || !matches!(op, Op::Copy(_)))
                .collect()
        };
        let fused = |p: &Program| {
            p.code()
                .iter()
                .filter(|i| i.op.fused_parts().is_some())
                .count()
        };
        assert_eq!(fused(&kept), 0, "{graph}: a kept-pins build is not fused");
        assert!(fused(&shared) > 0, "{graph}: the shared build is");
        assert_eq!(ops(&kept, false), ops(&shared, false), "{graph}");
        let copies = |p: &Program| ops(p, true).len() - ops(p, false).len();
        assert!(
            copies(&shared) < copies(&kept),
            "{graph}: {} copies shared, {} kept",
            copies(&shared),
            copies(&kept)
        );
        assert_eq!(kept.variables().len(), shared.variables().len());
        // An instance is smaller by exactly the slots it no longer holds.
        let skeleton = strider::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
            .expect("skeleton")
            .skeleton;
        let bytes = |p: Program| {
            Instance::new(Arc::new(p), Arc::clone(&skeleton))
                .expect("instance")
                .memory_bytes()
        };
        let sizes = [
            size_of::<bool>(),
            size_of::<i32>(),
            size_of::<f32>(),
            size_of::<glam::Vec3>(),
            size_of::<glam::Quat>(),
            size_of::<strider::Transform>(),
        ];
        let saved: usize = (0..6).map(|t| (k[t] - s[t]) * sizes[t]).sum();
        assert_eq!(bytes(kept) - bytes(shared), saved, "{graph}");
    }
}

/// Values that outlive the instructions around them in the ways sharing must respect:
/// `inv`, computed once before the loop, is read in every iteration, and `t3` is computed
/// after its read in the body (a slot shared with `inv` would give the second iteration
/// `t3`'s value); `Steps` is read before it is set (last frame's value); `held` is read in
/// both arms of a branch after a value computed in the first arm only.
const LIVES: &str = r#"
Graph(
    version: 1,
    name: "lives",
    variables: {
        "Items":  (type: FloatArray, default: [1.0, 2.0, 3.0]),
        "Factor": (type: Float, default: 3.0),
        "Sum":    (type: Float),
        "Steps":  (type: Float),
        "Flip":   (type: Bool),
        "Out":    (type: Float),
    },
    nodes: {
        "inv":        Multiply(a: var("Factor"), b: 2.0),
        "t1":         Add(a: "e", b: 1.0),
        "t2":         Multiply(a: "t1", b: "inv"),
        "t3":         Add(a: var("Sum"), b: "t2"),
        "dt":         DeltaTime(),
        "steps_next": Add(a: var("Steps"), b: "dt"),
        "held":       Multiply(a: var("Steps"), b: 10.0),
        "other":      Add(a: var("Factor"), b: 100.0),
        "both":       Add(a: "other", b: "held"),
        "not_flip":   Not(value: var("Flip")),
    },
    events: {
        forward: [
            Set("Sum", 0.0),
            ForEach(items: var("Items"), element: "e", body: [
                Set("Sum", "t3"),
            ]),
            Set("Out", "held"),
            Branch(condition: var("Flip"), then: [
                Set("Out", "both"),
            ], else: [
                Set("Out", "held"),
            ]),
            Set("Flip", "not_flip"),
            Set("Steps", "steps_next"),
        ],
    },
)
"#;

#[test]
fn values_live_across_loops_branches_and_frames_keep_their_slots() {
    let skeleton = strider::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
        .expect("skeleton")
        .skeleton;
    let program = Arc::new(compile_str(LIVES, false));
    let mut instance = Instance::new(Arc::clone(&program), skeleton).unwrap();
    let var = |instance: &Instance, name: &str| match instance
        .variable(program.variable_id(name).expect(name))
    {
        strider::nodes::Value::Float(x) => x,
        other => panic!("{name}: {other:?}"),
    };
    let input = FrameInput {
        dt: 0.25,
        ..FrameInput::default()
    };
    // Frame by frame, by hand: Sum = Σ (e + 1)·(2·Factor) = (2 + 3 + 4)·6; Steps gains dt
    // each frame; Out = Steps·10 of the frame's start, plus Factor + 100 on flipped frames.
    let expected_out = [0.0, 2.5 + 103.0, 5.0, 7.5 + 103.0];
    for (frame, out) in expected_out.into_iter().enumerate() {
        instance.run_forward(&input, &strider::EmptyWorld, false);
        assert_eq!(var(&instance, "Sum"), 54.0, "frame {frame}");
        assert_eq!(var(&instance, "Out"), out, "frame {frame}");
        assert_eq!(
            var(&instance, "Steps"),
            0.25 * (frame + 1) as f32,
            "frame {frame}"
        );
    }
    // It did share: fewer float slots than values.
    let kept = compile_str(LIVES, true);
    assert!(scalar_slots(&program)[2] < scalar_slots(&kept)[2]);
}

/// Copies the shared program leaves out, and the ones it must keep: a call's argument from
/// a variable (`Twice(x: var("B"))`), read where the variable is; the calls' results out of
/// the function, one of them on into a variable (`E`); a node's value set into a variable
/// by its producer (`y` into `D`, `later` into `C`, `chain` into `F`). `x` is set into `A`
/// and read again by `later` after `A` changes, so `x` keeps a slot apart from `A` and its
/// copy stays, as does the constant set into `A`.
const COPIES: &str = r#"
Graph(
    version: 1,
    name: "copies",
    variables: {
        "B": (type: Float, default: 5.0),
        "A": (type: Float),
        "C": (type: Float),
        "D": (type: Float),
        "E": (type: Float),
        "F": (type: Float),
    },
    functions: {
        "Twice": (
            inputs:  { "x": Float },
            outputs: { "y": Float },
            nodes:   { "double": Multiply(a: "x", b: 2.0) },
            exec:    [ Return(y: "double") ],
        ),
    },
    nodes: {
        "x":          Multiply(a: var("B"), b: 2.0),
        "later":      Add(a: "x", b: var("A")),
        "y":          Multiply(a: var("B"), b: 3.0),
        "from_var":   Twice(x: var("B")),
        "from_const": Twice(x: 4.0),
        "from_node":  Twice(x: "y"),
        "chain":      Add(a: "from_node", b: "from_const"),
    },
    events: {
        forward: [
            Set("A", "x"),
            Set("A", 7.0),
            Set("C", "later"),
            Set("D", "y"),
            Set("E", "from_var"),
            Set("F", "chain"),
        ],
    },
)
"#;

#[test]
fn copies_go_where_one_slot_can_hold_both_values() {
    let skeleton = strider::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
        .expect("skeleton")
        .skeleton;
    // By hand, with B = 5: x = 10, A = 7 after its second Set, later = x + A = 17,
    // y = 15, from_var = 10, from_const = 8, from_node = 30, chain = 38.
    let expected = [
        ("A", 7.0),
        ("C", 17.0),
        ("D", 15.0),
        ("E", 10.0),
        ("F", 38.0),
    ];
    let (kept, shared) = (compile_str(COPIES, true), compile_str(COPIES, false));
    let copies_into = |p: &Program| -> Vec<u32> {
        p.code()
            .iter()
            .filter(|i| matches!(i.op, Op::Copy(_)))
            .map(|i| p.operands()[i.args as usize + 1])
            .collect()
    };
    // Kept: the six Sets, the argument from a variable (a constant or a node's value is
    // read where it is) and the three results.
    assert_eq!(copies_into(&kept).len(), 10);
    // Shared: only the two Sets of A.
    let a = shared
        .variables()
        .iter()
        .find(|v| v.name == "A")
        .unwrap()
        .slot;
    assert_eq!(copies_into(&shared), [a, a]);
    for program in [kept, shared] {
        let program = Arc::new(program);
        let mut instance = Instance::new(Arc::clone(&program), Arc::clone(&skeleton)).unwrap();
        instance.run_forward(&FrameInput::default(), &strider::EmptyWorld, false);
        for (name, value) in expected {
            let id = program.variable_id(name).expect(name);
            assert_eq!(
                instance.variable(id),
                strider::nodes::Value::Float(value),
                "{name}"
            );
        }
    }
}
