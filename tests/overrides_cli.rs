//! `--overrides FILE` on `strider run`: tunable values from a file the inspector exports,
//! with `--set` winning, and a bad file reported with its line and column.

use std::process::Command;

fn strider(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_strider"))
        .args(args)
        .output()
        .expect("strider runs");
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).to_string(),
        String::from_utf8_lossy(&out.stderr).to_string(),
    )
}

fn write(name: &str, text: &str) -> String {
    let dir = std::env::temp_dir().join(format!("strider-overrides-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let path = dir.join(name);
    std::fs::write(&path, text).expect("write");
    path.to_string_lossy().into_owned()
}

/// pelvis_bob moves the pelvis by ±Amplitude around its rest height of 95 cm; a second of
/// frames at 60 Hz covers a whole period at the default frequency, so the summary's range
/// is 2 · Amplitude.
fn pelvis_range(extra: &[&str]) -> String {
    let mut args = vec![
        "run",
        "graphs/pelvis_bob.ron",
        "--skeleton",
        "graphs/skeletons/mannequin.ron",
        "--frames",
        "60",
    ];
    args.extend_from_slice(extra);
    let (ok, out, err) = strider(&args);
    assert!(ok, "{err}");
    out.lines()
        .find(|l| l.starts_with("pelvis z"))
        .map(|l| l.to_string())
        .unwrap_or_default()
}

#[test]
fn an_overrides_file_sets_tunables_and_set_wins() {
    assert!(pelvis_range(&[]).contains("(range 10.000 cm"));
    let file = write("amp.ron", "// tuned\n{ \"Amplitude\": 2.0 }\n");
    assert!(
        pelvis_range(&["--overrides", &file]).contains("(range 4.000 cm"),
        "{}",
        pelvis_range(&["--overrides", &file])
    );
    assert!(
        pelvis_range(&["--overrides", &file, "--set", "Amplitude=3"]).contains("(range 6.000 cm")
    );
}

#[test]
fn a_bad_overrides_file_is_reported_at_its_line_and_column() {
    let file = write("bad.ron", "{\n    \"Amplitud\": 2.0,\n}\n");
    let (ok, _, err) = strider(&[
        "run",
        "graphs/pelvis_bob.ron",
        "--skeleton",
        "graphs/skeletons/mannequin.ron",
        "--overrides",
        &file,
    ]);
    assert!(!ok);
    assert!(err.contains("bad.ron:2:5"), "{err}");
    assert!(err.contains("Amplitude"), "a suggestion: {err}");
}
