//! Every graph shipped under `graphs/` loads, compiles, instantiates on the mannequin and
//! runs; the example graphs compute what they are documented to compute.

use std::path::{Path, PathBuf};
use std::sync::Arc;
use strider_core::{DebugPrimitive, EmptyWorld, Vec3};
use strider_nodes::Value;
use strider_vm::{FrameInput, Instance};

fn mannequin() -> strider_graph::SkeletonFile {
    strider_graph::load_skeleton(Path::new("graphs/skeletons/mannequin.ron")).unwrap_or_else(|d| {
        panic!(
            "{}",
            d.iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join("\n")
        )
    })
}

fn compile(path: &Path) -> strider_vm::Program {
    strider_compiler::compile_file(path).unwrap_or_else(|d| {
        panic!(
            "{}",
            d.iter()
                .map(ToString::to_string)
                .collect::<Vec<_>>()
                .join("\n")
        )
    })
}

fn graph_files(dir: &Path, out: &mut Vec<PathBuf>) {
    for entry in std::fs::read_dir(dir).unwrap() {
        let path = entry.unwrap().path();
        if path.is_dir() {
            if path
                .file_name()
                .is_some_and(|n| n != "skeletons" && n != "scenarios")
            {
                graph_files(&path, out);
            }
        } else if path.extension().is_some_and(|e| e == "ron") {
            out.push(path);
        }
    }
}

#[test]
fn every_shipped_graph_compiles_and_runs() {
    let skeleton = mannequin();
    let mut files = Vec::new();
    graph_files(Path::new("graphs"), &mut files);
    assert!(files.len() >= 2, "found {files:?}");
    for file in files {
        let program = Arc::new(compile(&file));
        let mut instance = Instance::new(program, skeleton.skeleton.clone())
            .unwrap_or_else(|e| panic!("{}: {e}", file.display()));
        for _ in 0..30 {
            instance.run_forward(
                &FrameInput {
                    dt: 1.0 / 60.0,
                    ..Default::default()
                },
                &EmptyWorld,
                true,
            );
        }
        assert!(
            instance.pose_mut().globals().iter().all(|t| t.is_finite()),
            "{}",
            file.display()
        );
    }
}

#[test]
fn feet_finder_finds_feet_hands_soles_and_knees() {
    let skeleton = mannequin();
    let s = &skeleton.skeleton;
    let program = Arc::new(compile(Path::new("graphs/examples/feet_finder.ron")));
    let mut instance = Instance::new(program.clone(), s.clone()).unwrap();
    let var = |name: &str| program.variable_id(name).unwrap();

    // Feet and hands in hierarchy order, left first (the file lists left limbs first).
    let bones = |names: &[&str]| {
        Value::Array(
            strider_nodes::Elem::Bone,
            names
                .iter()
                .map(|n| Value::Bone(Some(n.to_string())))
                .collect(),
        )
    };
    assert_eq!(
        instance.variable(var("FootArray")),
        bones(&["foot_l", "foot_r"])
    );
    assert_eq!(
        instance.variable(var("HandArray")),
        bones(&["hand_l", "hand_r"])
    );

    // Soles: the ankle's rest position dropped by 13.5 cm lands on the ground (z = 0).
    let Value::Array(_, soles) = instance.variable(var("LockedFootLocationArray")) else {
        panic!()
    };
    assert_eq!(soles.len(), 2);
    for (sole, foot) in soles.iter().zip(["foot_l", "foot_r"]) {
        let Value::Transform(t) = sole else { panic!() };
        let ankle = s.rest_global(s.find(foot).unwrap()).translation;
        assert!((t.translation - (ankle - Vec3::new(0.0, 0.0, 13.5))).length() < 1e-4);
        assert!(t.translation.z.abs() < 1e-4, "sole z {}", t.translation.z);
    }

    // Knee vectors: calf − midpoint(thigh, foot), computed here from the skeleton directly.
    let Value::Array(_, knees) = instance.variable(var("DefaultKneeVectorArray")) else {
        panic!()
    };
    for (knee, side) in knees.iter().zip(["l", "r"]) {
        let p = |n: &str| {
            s.rest_global(s.find(&format!("{n}_{side}")).unwrap())
                .translation
        };
        let expected = p("calf") - (p("thigh") + p("foot")) * 0.5;
        let Value::Vec3(k) = knee else { panic!() };
        assert!((*k - expected).length() < 1e-4, "{k} vs {expected}");
        // The mannequin's knees bend forward (+Y).
        assert!(k.y > 0.0);
    }

    // Drawing: per foot one line (red left, blue right) and one transform; per hand a point.
    instance.run_forward(
        &FrameInput {
            dt: 1.0 / 60.0,
            ..Default::default()
        },
        &EmptyWorld,
        true,
    );
    let prims = instance.debug_draw().primitives();
    let lines: Vec<_> = prims
        .iter()
        .filter_map(|p| match p {
            DebugPrimitive::Line { color, .. } => Some(color.0),
            _ => None,
        })
        .collect();
    assert_eq!(lines, vec![[1.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0, 1.0]]);
    assert_eq!(
        prims
            .iter()
            .filter(|p| matches!(p, DebugPrimitive::Axes { .. }))
            .count(),
        2
    );
    assert_eq!(
        prims
            .iter()
            .filter(|p| matches!(p, DebugPrimitive::Point { .. }))
            .count(),
        2
    );

    // Without debug drawing nothing is recorded.
    instance.run_forward(
        &FrameInput {
            dt: 1.0 / 60.0,
            ..Default::default()
        },
        &EmptyWorld,
        false,
    );
    assert!(instance.debug_draw().primitives().is_empty());
}

#[test]
fn node_reference_is_current() {
    let expected = strider_nodes::registry().markdown();
    let actual = std::fs::read_to_string("docs/nodes.md").unwrap_or_default();
    assert!(
        actual == expected,
        "docs/nodes.md is out of date: run `cargo run -q -- nodes --markdown > docs/nodes.md`"
    );
}
