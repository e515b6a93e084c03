//! `strider bench`: its JSON carries every figure the performance targets are checked
//! against, consistent with each other, and a crowd makes no heap allocation per frame.

use std::process::Command;

fn bench(args: &[&str]) -> (bool, serde_json::Value, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_strider"))
        .arg("bench")
        .args(args)
        .output()
        .expect("strider runs");
    let stdout = String::from_utf8_lossy(&out.stdout).to_string();
    let stderr = String::from_utf8_lossy(&out.stderr).to_string();
    let json = serde_json::from_str(&stdout).unwrap_or(serde_json::Value::Null);
    (out.status.success(), json, stderr)
}

fn f(v: &serde_json::Value) -> f64 {
    v.as_f64().unwrap_or_else(|| panic!("not a number: {v}"))
}

#[test]
fn a_crowd_on_two_threads_reports_every_figure() {
    let (ok, j, err) = bench(&[
        "graphs/foot_ik.ron",
        "--skeleton",
        "graphs/skeletons/mannequin.ron",
        "--scenario",
        "graphs/scenarios/standing_on_stairs.ron",
        "--characters",
        "6",
        "--frames",
        "4",
        "--repetitions",
        "3",
        "--threads",
        "2",
        "--warm-up",
        "40",
        "--json",
    ]);
    assert!(ok, "{err}");
    assert_eq!(j["characters"], 6);
    assert_eq!(j["threads"], 2);
    // By default the interpreter runs characters 16 at a time (here all 6 together, 3 on
    // each thread), and still gives the native baseline's outputs (below).
    assert_eq!(j["batch"], 16);
    assert!(j["cores"].as_u64().is_some_and(|c| c >= 1));
    let ns = &j["ns_per_character_frame"];
    let (median, min, max) = (f(&ns["median"]), f(&ns["min"]), f(&ns["max"]));
    assert!(0.0 < min && min <= median && median <= max, "{ns}");
    // Characters per 60 Hz frame = 16.67 ms / time per character-frame.
    let per_frame = f(&j["characters_per_16ms"]);
    assert!(
        (per_frame * median - 1e9 / 60.0).abs() < 1.0,
        "{per_frame} x {median}"
    );
    assert!(f(&j["compile_ms"]) > 0.0);
    // Every thread count from 1 to 2, the first with a speed-up of exactly 1.
    let scaling = j["scaling"].as_array().expect("scaling");
    assert_eq!(scaling.len(), 2);
    assert_eq!(scaling[0]["threads"], 1);
    assert_eq!(f(&scaling[0]["speedup"]), 1.0);
    assert_eq!(scaling[1]["threads"], 2);
    // foot_ik has a native baseline: measured, and its outputs equal the interpreter's.
    assert!(f(&j["native_ratio"]) > 0.0);
    assert_eq!(j["native_identical"], true);
    // The counting allocator is installed in the binary, and nothing allocates per frame.
    assert_eq!(f(&j["allocations_per_frame"]), 0.0, "{j}");
    // An instance holds at least its pose: two transforms per mannequin bone (23).
    let pose = 2.0 * 23.0 * size_of::<strider::Transform>() as f64;
    assert!(f(&j["instance_bytes"]) > pose, "{j}");
}

/// Locomotion runs on lanes, where a batch does not copy back the slots of values that
/// live only within a run: the bench still finds its outputs bit-identical to the native
/// code's (its last check frame runs with debug, which brings every slot back), on either
/// copy of the batch loop.
#[test]
fn a_batched_locomotion_crowd_matches_its_native_code_on_either_batch_loop() {
    for baseline in [false, true] {
        let mut args = vec![
            "graphs/locomotion.ron",
            "--skeleton",
            "graphs/skeletons/mannequin.ron",
            "--scenario",
            "graphs/scenarios/strafe_8dir.ron",
            "--characters",
            "17",
            "--frames",
            "2",
            "--repetitions",
            "1",
            "--threads",
            "1",
            "--warm-up",
            "30",
            "--json",
        ];
        if baseline {
            // With the crowd in scrambled order too: other batches, the same answers.
            args.extend(["--baseline-code", "--shuffle"]);
        }
        let (ok, j, err) = bench(&args);
        assert!(ok, "{err}");
        assert_eq!(j["batch"], 16);
        assert_eq!(j["shuffled"], baseline);
        assert_eq!(j["native_identical"], true, "{j}");
        let code = j["batch_code"].as_str().expect("batch_code");
        if baseline {
            assert_eq!(code, "baseline");
        } else {
            assert_eq!(code, strider::vm::batch_code().name());
        }
    }
}

#[test]
fn a_graph_without_native_code_has_no_ratio() {
    let (ok, j, err) = bench(&[
        "graphs/pelvis_bob.ron",
        "--skeleton",
        "graphs/skeletons/mannequin.ron",
        "--scenario",
        "graphs/scenarios/walk_flat.ron",
        "--characters",
        "3",
        "--frames",
        "2",
        "--repetitions",
        "1",
        "--threads",
        "1",
        "--warm-up",
        "5",
        "--batch",
        "1",
        "--json",
    ]);
    assert!(ok, "{err}");
    assert_eq!(j["batch"], 1);
    assert!(j["native_ratio"].is_null(), "{j}");
    assert!(j["native_identical"].is_null());
}

#[test]
fn bad_input_is_an_error_naming_the_file() {
    let (ok, _, err) = bench(&[
        "graphs/foot_ik.ron",
        "--skeleton",
        "graphs/skeletons/mannequin.ron",
        "--scenario",
        "graphs/scenarios/no_such_scenario.ron",
    ]);
    assert!(!ok);
    assert!(err.contains("no_such_scenario.ron"), "{err}");
    // Out-of-range counts: the error names the option and its range.
    for (option, value, range) in [
        ("--characters", "0", "1..=1000000"),
        ("--batch", "0", "1..=16"),
        ("--batch", "17", "1..=16"),
    ] {
        let (ok, _, err) = bench(&[
            "graphs/foot_ik.ron",
            "--skeleton",
            "graphs/skeletons/mannequin.ron",
            "--scenario",
            "graphs/scenarios/walk_flat.ron",
            option,
            value,
        ]);
        assert!(!ok);
        assert!(err.contains(option) && err.contains(range), "{err}");
    }
}
