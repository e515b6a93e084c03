//! The inspector opened headless on the locomotion graph (egui_kittest): read a live pin
//! value, scrub back in time, change a tunable, break the graph file and keep walking.
//!
//! Paths are relative to this crate's folder (the tests' working directory), so what the
//! panels print does not depend on where the repository is checked out. Snapshots are
//! written under the repository's `tests/snapshots/` (`UPDATE_SNAPSHOTS=1` refreshes
//! them; the tolerance is in `kittest.toml`).

use egui::Key;
use egui_kittest::kittest::Queryable;
use egui_kittest::{Harness, SnapshotOptions};
use glam::{Vec2, Vec3};
use std::path::{Path, PathBuf};
use std::time::{Duration, Instant};
use strider_host::mover::{Facing, MoveInput};
use strider_inspector::recording::ARRAY_BUDGET;
use strider_inspector::values::{ValueSource, format_value};
use strider_inspector::{InspectOptions, InspectorApp, Session};
use strider_nodes::Value;

const GRAPHS: &str = "../../graphs";

fn options(graph: &Path) -> InspectOptions {
    InspectOptions {
        graph: graph.to_path_buf(),
        skeleton: PathBuf::from(GRAPHS).join("skeletons/mannequin.ron"),
        scenario: None,
        world: None,
        overrides: None,
    }
}

fn harness(options: InspectOptions) -> Harness<'static, InspectorApp> {
    let session = Session::open(options).expect("the locomotion graph loads");
    let mut harness = Harness::builder()
        .with_size([1600.0, 950.0])
        .with_step_dt(1.0 / 60.0)
        .build_eframe(move |cc| {
            let mut app = InspectorApp::new(&cc.egui_ctx, session);
            // The tests step the simulation themselves (deterministic frames).
            app.playback.playing = false;
            app
        });
    harness.run_steps(2);
    harness
}

/// Runs `frames` simulation frames walking at `speed` cm/s along world `direction`.
fn walk(harness: &mut Harness<'_, InspectorApp>, direction: Vec2, speed: f32, frames: u32) {
    let app = harness.state_mut();
    app.session.input = MoveInput {
        direction,
        speed,
        facing: Facing::Velocity,
    };
    app.advance(frames);
}

/// Index of the node labelled `label` in the graph view's open body.
fn node_index(app: &InspectorApp, label: &str) -> usize {
    app.graph
        .body()
        .nodes
        .iter()
        .position(|n| n.label() == label)
        .unwrap_or_else(|| panic!("no node `{label}` in the open body"))
}

fn pelvis_world(app: &InspectorApp) -> Vec3 {
    let frame = app.session.recorder().latest().expect("a frame");
    let pelvis = app
        .session
        .skeleton()
        .skeleton
        .find("pelvis")
        .expect("mannequin pelvis");
    frame
        .meta
        .to_world
        .transform_point(frame.globals[pelvis.0 as usize].translation)
}

fn snapshot_options() -> SnapshotOptions {
    SnapshotOptions::new()
        .output_path(PathBuf::from(env!("CARGO_MANIFEST_DIR")).join("../../tests/snapshots"))
}

#[test]
fn selecting_a_node_shows_its_live_pin_values() {
    let mut harness = harness(options(&PathBuf::from(GRAPHS).join("locomotion.ron")));
    walk(&mut harness, Vec2::Y, 150.0, 120);
    {
        let app = harness.state_mut();
        let program = std::sync::Arc::clone(app.session.program());
        let loaded = std::sync::Arc::clone(app.session.document());
        assert!(
            app.graph
                .open_function_anywhere(&program, &loaded, "CalculateFootSpline"),
            "CalculateFootSpline is reached by a call path"
        );
    }
    harness.run_steps(3);
    // The breadcrumb shows the path from the graph to the function.
    harness.get_by_label("CalculateFootSpline");
    harness.get_by_label("CalculateFootTargetPlatform");
    // Click the node `clear_s`: MakeVector(z: var("SplineStartClearance")). The graph is
    // drawn in a zoomed layer: its widgets' rects are in graph coordinates.
    let title = harness.get_by_label("clear_s: MakeVector").rect().center();
    let layer = egui::LayerId::new(egui::Order::Background, egui::Id::new("strider-graph-view"));
    let at = harness
        .ctx
        .layer_transform_to_global(layer)
        .map_or(title, |t| t * title);
    harness.hover_at(at);
    harness.run_steps(1);
    harness.drag_at(at);
    harness.run_steps(1);
    harness.drop_at(at);
    harness.run_steps(3);
    let app = harness.state();
    let selected = app.graph.selected.expect("the click selects the node");
    assert_eq!(app.graph.body().nodes[selected].label(), "clear_s");
    // Its output is (0, 0, SplineStartClearance) with the file's 3 cm.
    harness.get_by_label("out result");
    harness.get_by_label("(0.0, 0.0, 3.0)");

    // Hovering the node's output pin shows the same value in a tooltip.
    let to_screen = |harness: &Harness<'_, InspectorApp>, p: egui::Pos2| {
        harness
            .ctx
            .layer_transform_to_global(layer)
            .map_or(p, |t| t * p)
    };
    let pin = harness
        .get_all_by_label("result")
        .map(|n| n.rect())
        // In the node: below its title, within a node's width to its right.
        .filter(|r| {
            r.center().y > title.y && r.center().x > title.x && r.center().x < title.x + 250.0
        })
        .min_by(|a, b| (a.center().y - title.y).total_cmp(&(b.center().y - title.y)))
        .expect("the output pin's label");
    let at = to_screen(&harness, pin.center());
    // Moved onto the pin, then resting there.
    harness.hover_at(at - egui::vec2(1.0, 0.0));
    harness.run_steps(1);
    harness.hover_at(at);
    // Tooltips wait until the pointer has rested a moment (egui's tooltip delay).
    harness.run_steps(60);
    assert_eq!(
        harness.query_all_by_label("(0.0, 0.0, 3.0)").count(),
        2,
        "the node panel and the pin's tooltip"
    );
}

/// The whole window on a small frozen graph (tests/data/bob.ron), after 0.25 s: a node
/// selected, a plot, the comment box of the file's editor section.
#[test]
fn snapshot_of_the_window() {
    let mut harness = harness(options(Path::new("tests/data/bob.ron")));
    {
        let app = harness.state_mut();
        app.advance(14);
        assert!(app.graph.select("offset"));
        let id = app.session.program().variable_id("Time").expect("declared");
        let info = app.session.program().variable(id).clone();
        app.plots
            .add("Time", info.ty, info.slot, app.session.generation());
    }
    harness.run_steps(3);
    // 15 frames of 1/60 s (the app runs one when it opens): `Set("Time", "t")` comes
    // first, so the pelvis step reads Time = 15/60 s, and `offset` = (0, 0, 5 cm ·
    // sin(360° · 1 Hz · 0.25 s)) = (0, 0, 5 cm).
    harness.get_by_label("(0.0, 0.0, 5.0)");
    harness.snapshot_options("inspector_bob", &snapshot_options());
}

#[test]
fn scrubbing_back_shows_older_values() {
    let mut harness = harness(options(&PathBuf::from(GRAPHS).join("locomotion.ron")));
    // Stand 3 s, then walk 3 s: IsMoving is false while standing and true walking.
    walk(&mut harness, Vec2::ZERO, 0.0, 180);
    walk(&mut harness, Vec2::Y, 150.0, 180);
    harness.state_mut().variables.filter = "IsMoving".to_string();
    harness.run_steps(2);
    harness.get_by_label("All variables (frame shown)").click();
    harness.run_steps(2);
    assert!(
        harness.query_by_label("true").is_some(),
        "walking: IsMoving is true"
    );

    // Travel back 5 s: into the standing second.
    {
        let app = harness.state_mut();
        let recorder = app.session.recorder();
        let live_time = recorder.latest().expect("frames").meta.time;
        app.playback.scrub_back(app.session.recorder(), 5.0);
        let shown = app.playback.shown(app.session.recorder()).expect("a frame");
        let t = app.session.recorder().get(shown).expect("kept").meta.time;
        assert!(
            (live_time - t - 5.0).abs() < 1.0 / 60.0 + 1e-9,
            "{live_time} {t}"
        );
        let id = app
            .session
            .program()
            .variable_id("IsMoving")
            .expect("declared");
        let info = app.session.program().variable(id).clone();
        let value = ValueSource::of(&app.session, Some(shown)).read(info.ty, info.slot);
        assert_eq!(value, Some(Value::Bool(false)));
    }
    harness.run_steps(2);
    assert!(
        harness.query_by_label("false").is_some(),
        "standing: IsMoving is false"
    );
    assert!(harness.query_by_label("true").is_none());
    // The timeline says how far back the frame is.
    harness.get_by_label_contains("(-5.00 s)");
    // Playing again returns to the live frame.
    harness.get_by_label("▶ Play").click();
    harness.run_steps(2);
    assert!(harness.state().playback.cursor.is_none());
}

#[test]
fn scrubbing_back_shows_older_array_values() {
    let mut harness = harness(options(&PathBuf::from(GRAPHS).join("locomotion.ron")));
    let (id, ty, slot) = {
        let program = harness.state().session.program();
        let id = program
            .variable_id("PerFootCyclePercentArray")
            .expect("declared");
        (id, program.variable(id).ty, program.variable(id).slot)
    };
    // Walk 2 s, noting the array's live value after each frame.
    let mut live = Vec::new();
    for _ in 0..120 {
        walk(&mut harness, Vec2::Y, 150.0, 1);
        let app = harness.state();
        live.push((app.session.frame() - 1, app.session.instance().variable(id)));
    }
    let newest = live.last().expect("frames").1.clone();
    // Travel back 1 s: the array as it was then, not as it is now.
    let expected = {
        let app = harness.state_mut();
        app.playback.scrub_back(app.session.recorder(), 1.0);
        let shown = app.playback.shown(app.session.recorder()).expect("a frame");
        let frame = app.session.recorder().get(shown).expect("kept").meta.frame;
        let (_, then) = live
            .iter()
            .find(|(f, _)| *f == frame)
            .expect("a frame of the walk");
        let value = ValueSource::of(&app.session, Some(shown)).read(ty, slot);
        assert_eq!(value.as_ref(), Some(then));
        assert!(matches!(then, Value::Array(_, items) if items.len() == 2));
        assert_ne!(*then, newest, "the feet's cycles moved on in 1 s");
        then.clone()
    };
    // The variables panel shows it too.
    harness.state_mut().variables.filter = "PerFootCyclePercentArray".to_string();
    harness.run_steps(2);
    harness.get_by_label("All variables (frame shown)").click();
    harness.run_steps(2);
    harness.get_by_label(&format_value(&expected));
}

/// Highest world height of the left ball joint over the recorded frames of the current
/// program.
fn highest_ball(app: &InspectorApp) -> f32 {
    let ball = app
        .session
        .skeleton()
        .skeleton
        .find("ball_l")
        .expect("mannequin ball_l");
    app.session
        .recorder()
        .iter()
        .filter(|f| f.meta.generation == app.session.generation())
        .skip(60)
        .map(|f| {
            f.meta
                .to_world
                .transform_point(f.globals[ball.0 as usize].translation)
                .z
        })
        .fold(f32::MIN, f32::max)
}

#[test]
fn a_higher_lift_tunable_lifts_the_swinging_foot_higher() {
    let mut a = harness(options(&PathBuf::from(GRAPHS).join("locomotion.ron")));
    let mut b = harness(options(&PathBuf::from(GRAPHS).join("locomotion.ron")));
    // Raise SplineLiftStart and SplineLiftEnd (the swing curve's lift above its ends) with
    // the variables panel's sliders, typed in as a person would.
    for name in ["SplineLiftStart", "SplineLiftEnd"] {
        b.state_mut().variables.filter = name.to_string();
        b.run_steps(2);
        // The slider's value field shows the file's default (10 and 30 cm); a click opens
        // it for typing with its text selected.
        let default = if name == "SplineLiftStart" {
            "10.0"
        } else {
            "30.0"
        };
        b.get_by_value(default).click();
        b.run_steps(1);
        b.event(egui::Event::Text("60".to_string()));
        b.key_press(Key::Enter);
        b.run_steps(2);
        let app = b.state();
        let id = app.session.program().variable_id(name).expect("declared");
        assert_eq!(
            app.session.instance().variable(id),
            Value::Float(60.0),
            "{name}"
        );
    }
    walk(&mut a, Vec2::Y, 150.0, 240);
    walk(&mut b, Vec2::Y, 150.0, 240);
    let (low, high) = (highest_ball(a.state()), highest_ball(b.state()));
    assert!(
        high > low + 5.0,
        "doubling the lift (30 → 60 cm at full curve speed) raises the foot: {low} → {high}"
    );
    // Reset puts the file's default back (after a frame laid out with the new quality
    // figures, which move the panel's rows).
    b.run_steps(2);
    b.get_by_label("↺").click();
    b.run_steps(2);
    let app = b.state();
    let id = app
        .session
        .program()
        .variable_id("SplineLiftEnd")
        .expect("declared");
    assert_eq!(app.session.instance().variable(id), Value::Float(30.0));
}

/// A fresh folder under the system's temporary folder.
fn scratch_dir(name: &str) -> PathBuf {
    let nanos = std::time::SystemTime::now()
        .duration_since(std::time::UNIX_EPOCH)
        .map_or(0, |d| d.as_nanos());
    let dir = std::env::temp_dir().join(format!(
        "strider-inspector-{name}-{}-{nanos}",
        std::process::id()
    ));
    std::fs::create_dir_all(&dir).expect("temp dir");
    dir
}

/// Steps the UI until `done` or `timeout` (file events arrive from another thread).
fn wait_until(
    harness: &mut Harness<'_, InspectorApp>,
    timeout: Duration,
    done: impl Fn(&InspectorApp) -> bool,
) -> bool {
    let start = Instant::now();
    while start.elapsed() < timeout {
        harness.step();
        if done(harness.state()) {
            return true;
        }
        std::thread::sleep(Duration::from_millis(20));
    }
    false
}

#[test]
fn a_broken_graph_file_shows_a_diagnostic_while_the_character_keeps_walking() {
    let dir = scratch_dir("reload");
    let graph = dir.join("locomotion.ron");
    let text = std::fs::read_to_string(PathBuf::from(GRAPHS).join("locomotion.ron")).expect("read");
    std::fs::write(&graph, &text).expect("copy");
    let mut harness = harness(options(&graph));
    walk(&mut harness, Vec2::Y, 150.0, 60);
    // A tuned value survives reloads.
    {
        let app = harness.state_mut();
        let id = app
            .session
            .program()
            .variable_id("SplineLiftEnd")
            .expect("declared");
        app.session
            .set_variable(id, &Value::Float(42.0))
            .expect("float");
    }

    // Misspell a node type inside CalculateFootSpline.
    let needle = "\"dir\":       Unit(";
    let at = text.find(needle).expect("the graph has the `dir` node") + "\"dir\":       ".len();
    let line = text[..at].lines().count();
    let col = at - text[..at].rfind('\n').map_or(0, |i| i + 1) + 1;
    let broken = text.replacen(needle, "\"dir\":       Unti(", 1);
    std::fs::write(&graph, &broken).expect("write broken");
    assert!(
        wait_until(&mut harness, Duration::from_secs(10), |app| !app
            .session
            .problems()
            .is_empty()),
        "the watcher sees the change and the reload reports it"
    );
    let expected = format!("locomotion.ron:{line}:{col}: error:");
    let problems = harness.state().session.problems().join("\n");
    assert!(
        problems.contains(&expected),
        "expected `{expected}` in:\n{problems}"
    );
    assert!(problems.contains("Unti"), "{problems}");
    harness.run_steps(2);
    harness.get_by_label_contains(&expected);
    harness.get_by_label_contains("problem(s): running the last good program");

    // The last good program keeps running: the character walks on (1 s at 150 cm/s).
    let before = pelvis_world(harness.state());
    walk(&mut harness, Vec2::Y, 150.0, 60);
    let after = pelvis_world(harness.state());
    assert!(after.y - before.y > 100.0, "{before:?} → {after:?}");

    // Fixed: the reload succeeds, the problems go, the tuned value is still there.
    std::fs::write(&graph, &text).expect("write fixed");
    assert!(
        wait_until(&mut harness, Duration::from_secs(10), |app| app
            .session
            .problems()
            .is_empty()),
        "the fixed file reloads"
    );
    let app = harness.state();
    let id = app
        .session
        .program()
        .variable_id("SplineLiftEnd")
        .expect("declared");
    assert_eq!(app.session.instance().variable(id), Value::Float(42.0));
    // The user's file is exactly what they wrote.
    assert_eq!(std::fs::read_to_string(&graph).expect("read"), text);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_keyboard_drives_the_character_relative_to_the_camera() {
    let mut harness = harness(options(&PathBuf::from(GRAPHS).join("locomotion.ron")));
    harness.state_mut().playback.playing = true;
    // The camera looks along +Y (yaw 0): W walks towards +Y, A towards +X (screen left).
    harness.key_down(Key::W);
    harness.run_steps(60);
    harness.key_up(Key::W);
    let p = harness.state().session.component_to_world().translation;
    assert!(p.y > 30.0 && p.x.abs() < 5.0, "{p:?}");
    harness.key_down(Key::A);
    harness.run_steps(60);
    harness.key_up(Key::A);
    let q = harness.state().session.component_to_world().translation;
    assert!(q.x - p.x > 30.0, "{p:?} → {q:?}");
}

#[test]
fn exported_overrides_are_read_back_by_a_new_session() {
    let dir = scratch_dir("overrides");
    let mut harness = harness(options(&PathBuf::from(GRAPHS).join("locomotion.ron")));
    let file = dir.join("tuned.ron");
    {
        let app = harness.state_mut();
        let id = app
            .session
            .program()
            .variable_id("SplineLiftEnd")
            .expect("declared");
        app.session
            .set_variable(id, &Value::Float(12.5))
            .expect("float");
        app.variables.overrides_path = file.display().to_string();
        // A short list, so that the buttons below it are on screen.
        app.variables.filter = "SplineLift".to_string();
    }
    harness.run_steps(2);
    harness.get_by_label("Export").click();
    harness.run_steps(2);
    assert!(file.exists());
    // Exporting over the graph file is refused.
    {
        let app = harness.state();
        let err = app
            .session
            .export_overrides(&app.session.options().graph)
            .expect_err("never rewrite the graph");
        assert!(
            err.contains("one of the files the inspector reads"),
            "{err}"
        );
    }
    let mut opts = options(&PathBuf::from(GRAPHS).join("locomotion.ron"));
    opts.overrides = Some(file.clone());
    let session = Session::open(opts).expect("opens with the overrides");
    let id = session
        .program()
        .variable_id("SplineLiftEnd")
        .expect("declared");
    assert_eq!(session.instance().variable(id), Value::Float(12.5));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn without_a_display_run_names_the_headless_commands() {
    let saved: Vec<_> = ["DISPLAY", "WAYLAND_DISPLAY"]
        .iter()
        .map(|v| (*v, std::env::var_os(v)))
        .collect();
    if saved.iter().any(|(_, v)| v.is_some()) {
        // A display is present: opening a real window is not this test's business.
        return;
    }
    let err = strider_inspector::run(options(&PathBuf::from(GRAPHS).join("locomotion.ron")))
        .expect_err("no display");
    let text = err.to_string();
    assert!(text.contains("needs a display"), "{text}");
    assert!(
        text.contains("strider run") && text.contains("strider report"),
        "{text}"
    );
}

#[test]
fn the_recording_keeps_a_bounded_number_of_frames() {
    let mut session =
        Session::open(options(&PathBuf::from(GRAPHS).join("locomotion.ron"))).expect("loads");
    let capacity = session.recorder().capacity();
    // At least 30 s at 60 Hz.
    assert!(capacity >= 30 * 60, "{capacity}");
    session.input = MoveInput {
        direction: Vec2::Y,
        speed: 150.0,
        facing: Facing::Velocity,
    };
    for _ in 0..capacity + 30 {
        session.step();
    }
    let recorder = session.recorder();
    assert_eq!(recorder.len(), capacity);
    // Oldest first, one frame apart, the newest being the last frame run.
    let first = recorder.get(0).expect("kept").meta.frame;
    let last = recorder.latest().expect("kept").meta.frame;
    assert_eq!(last, session.frame() - 1);
    assert_eq!(last - first, capacity as u64 - 1);
    assert!(
        recorder
            .iter()
            .zip(recorder.iter().skip(1))
            .all(|(a, b)| b.meta.frame == a.meta.frame + 1)
    );
    // The oldest frames came after the first keyframe (frame 0, no longer recorded) and
    // before the next one: shown, but not resumed from; a later one is.
    let first_kept = session.recorder().get(0).expect("kept").meta.frame;
    assert_eq!(first_kept, 30);
    let err = session.resume_from(0).expect_err("no keyframe since");
    assert!(err.contains("cannot resume from t 0.52 s"), "{err}");
    assert!(err.contains("resumed from t 1.00 s on"), "{err}");
    let recorder = session.recorder();
    assert_eq!(recorder.len(), capacity);
    // A frame holds the instance's slots (array items included), the pose and the debug
    // drawing.
    let slots = session.instance().slots();
    let scalars = slots.bools.len()
        + 4 * (slots.ints.len() + slots.floats.len() + slots.bones.len())
        + std::mem::size_of::<glam::Vec3>() * slots.vec3s.len()
        + std::mem::size_of::<glam::Quat>() * slots.quats.len()
        + std::mem::size_of::<strider_core::Transform>() * slots.transforms.len();
    let items = slots.bool_arrays.iter().map(Vec::len).sum::<usize>()
        + 4 * slots.int_arrays.iter().map(Vec::len).sum::<usize>()
        + 4 * slots.float_arrays.iter().map(Vec::len).sum::<usize>()
        + 4 * slots.bone_arrays.iter().map(Vec::len).sum::<usize>()
        + std::mem::size_of::<glam::Vec3>() * slots.vec3_arrays.iter().map(Vec::len).sum::<usize>()
        + std::mem::size_of::<glam::Quat>() * slots.quat_arrays.iter().map(Vec::len).sum::<usize>()
        + std::mem::size_of::<strider_core::Transform>()
            * slots.transform_arrays.iter().map(Vec::len).sum::<usize>();
    assert!(items > 0, "the locomotion graph has arrays");
    assert!(
        items <= ARRAY_BUDGET,
        "{items} bytes of arrays fit the budget"
    );
    let frame = recorder.latest().expect("kept");
    assert!(frame.slots.bytes() >= scalars + items);
    // The array items' memory stays within the budget in every frame.
    assert!(
        recorder
            .iter()
            .all(|f| f.slots.array_capacity_bytes() <= ARRAY_BUDGET)
    );
    let per_frame = recorder.bytes_per_frame();
    assert!(per_frame >= scalars + items);
    let total = recorder.bytes();
    eprintln!(
        "recording: {per_frame} bytes in the newest frame ({} of slots, of which {items} of \
         array items; {} debug primitives), {:.1} MB for {capacity} frames",
        frame.slots.bytes(),
        frame.debug.len(),
        total as f64 / 1.0e6
    );

    // Resuming inside the full ring keeps the frames before, oldest first, and drops the
    // rest; the ring then fills again.
    session
        .resume_from(100)
        .expect("frame 130: after the keyframe at 120");
    let recorder = session.recorder();
    assert_eq!(recorder.len(), 101);
    assert_eq!(recorder.get(0).expect("kept").meta.frame, 30);
    assert_eq!(recorder.latest().expect("kept").meta.frame, 130);
    session.step();
    assert_eq!(session.recorder().len(), 102);
    assert_eq!(session.recorder().latest().expect("kept").meta.frame, 131);
}

#[cfg(feature = "profile")]
#[test]
fn time_per_node_prints_microseconds_on_the_nodes() {
    let mut harness = harness(options(Path::new("tests/data/bob.ron")));
    // Times are averaged over half a second of frames.
    harness.state_mut().advance(60);
    assert!(harness.state().session.profile_us().is_some());
    harness.state_mut().graph.show_profile = true;
    harness.run_steps(3);
    // Every declared node of the top level runs each frame: each prints its time.
    let declared = 9;
    let timed = harness.get_all_by_label_contains(" µs").count();
    assert!(timed >= declared, "{timed} nodes print a time");
}

#[test]
fn a_reload_keeps_the_state_the_frames_built() {
    let dir = scratch_dir("state");
    let graph = dir.join("locomotion.ron");
    let text = std::fs::read_to_string(PathBuf::from(GRAPHS).join("locomotion.ron")).expect("read");
    std::fs::write(&graph, &text).expect("copy");
    let mut harness = harness(options(&graph));
    walk(&mut harness, Vec2::Y, 150.0, 90);
    let before: Vec<Value> = {
        let app = harness.state();
        let program = app.session.program();
        (0..program.variables().len())
            .map(|i| {
                app.session
                    .instance()
                    .variable(strider_vm::VariableId(i as u32))
            })
            .collect()
    };
    // Only a comment changes: the program is the same, and so must be every variable —
    // the state the 90 frames built (feet, velocity, cycle) and what `construction` set.
    std::fs::write(&graph, format!("{text}\n// edited\n")).expect("edit");
    assert!(
        wait_until(&mut harness, Duration::from_secs(10), |app| app
            .session
            .status()
            .starts_with("reloaded")),
        "the edit reloads"
    );
    let app = harness.state();
    assert!(app.session.problems().is_empty());
    let program = app.session.program();
    for (i, v) in program.variables().iter().enumerate() {
        let now = app
            .session
            .instance()
            .variable(strider_vm::VariableId(i as u32));
        assert_eq!(now, before[i], "{}", v.name);
    }
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn a_reload_takes_what_the_edited_construction_gives() {
    let graph_text = |base: f32| {
        format!(
            r#"Graph(
    version: 1,
    name: "counter",
    variables: {{ "Count": (type: Float), "Base": (type: Float) }},
    nodes: {{ "next": Add(a: var("Count"), b: 1.0) }},
    events: {{
        construction: [ Set("Base", {base:.1}) ],
        forward: [ Set("Count", "next") ],
    }},
)
"#
        )
    };
    let dir = scratch_dir("construction");
    let graph = dir.join("counter.ron");
    std::fs::write(&graph, graph_text(10.0)).expect("write");
    let mut harness = harness(options(&graph));
    harness.state_mut().advance(29);
    let get = |app: &InspectorApp, name: &str| {
        let id = app.session.program().variable_id(name).expect("declared");
        app.session.instance().variable(id)
    };
    // One frame when the app opens, 29 more: Count counted 30 frames.
    assert_eq!(get(harness.state(), "Count"), Value::Float(30.0));
    assert_eq!(get(harness.state(), "Base"), Value::Float(10.0));
    std::fs::write(&graph, graph_text(20.0)).expect("edit");
    assert!(
        wait_until(&mut harness, Duration::from_secs(10), |app| get(
            app, "Base"
        )
            == Value::Float(20.0)),
        "the edited construction's value is taken"
    );
    // The frames' state is kept (the app is paused: no frame ran since).
    assert_eq!(get(harness.state(), "Count"), Value::Float(30.0));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn the_quality_panel_measures_the_recorded_frames_of_the_run() {
    let mut harness = harness(options(&PathBuf::from(GRAPHS).join("locomotion.ron")));
    // One frame when the app opens, 299 more: 5 s walking at 150 cm/s.
    walk(&mut harness, Vec2::Y, 150.0, 299);
    {
        let session = &mut harness.state_mut().session;
        session.finish_quality();
        session.update_quality();
        session.finish_quality();
        let q = session.quality();
        let report = q.report.as_ref().expect("a report");
        assert_eq!((q.frames, report.frames), (300, 300));
        assert!(
            report.steps >= 4,
            "5 s of walking takes steps: {}",
            report.steps
        );
    }
    harness.run_steps(2);
    harness.get_by_label_contains("(300 frames) of the current program");
    assert!(
        harness.query_all_by_label("pass").count() + harness.query_all_by_label("FAIL").count()
            >= 7
    );
}

#[test]
fn a_graph_broken_at_launch_opens_with_its_problems_and_loads_once_fixed() {
    let dir = scratch_dir("launch");
    let graph = dir.join("bob.ron");
    let text = std::fs::read_to_string("tests/data/bob.ron").expect("read");
    // `Sin` misspelled on line 18 (`"sine":   Sin(value: "phase"),`).
    let broken = text.replacen("Sin(value", "Sinn(value", 1);
    let line = text[..text.find("Sin(value").expect("the sine node")]
        .lines()
        .count();
    std::fs::write(&graph, &broken).expect("write broken");
    let mut harness = harness(options(&graph));
    {
        let session = &harness.state().session;
        assert!(!session.graph_loaded());
        let problems = session.problems().join("\n");
        assert!(problems.contains(&format!("bob.ron:{line}:")), "{problems}");
    }
    harness.run_steps(2);
    // Said in the top bar and in the diagnostics panel.
    assert_eq!(
        harness
            .query_all_by_label_contains("nothing runs until the graph loads")
            .count(),
        2
    );
    std::fs::write(&graph, &text).expect("fix");
    assert!(
        wait_until(&mut harness, Duration::from_secs(10), |app| app
            .session
            .graph_loaded()),
        "the fixed graph loads"
    );
    let app = harness.state();
    assert!(app.session.problems().is_empty());
    assert_eq!(app.session.program().name(), "bob");
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn strafing_faces_the_point_under_the_mouse() {
    let mut harness = harness(options(&PathBuf::from(GRAPHS).join("locomotion.ron")));
    harness.state_mut().playback.playing = true;
    harness.key_press(Key::F);
    harness.run_steps(2);
    assert!(harness.state().controls.strafe, "F switches to strafing");
    // Aim at the ground on the left of the view: seen from behind (the camera looks along
    // +Y), that is the character's left, +X.
    let rect = harness.state().viewport.rect;
    harness.hover_at(rect.center() + egui::vec2(-rect.width() * 0.4, rect.height() * 0.1));
    harness.key_down(Key::W);
    harness.run_steps(90);
    harness.key_up(Key::W);
    let app = harness.state();
    let yaw = app.controls.look_yaw;
    // Yaw 0 faces +Y and positive yaw turns counter-clockwise, towards −X: +X is −90°;
    // the point is left of the view and in front of the character, so between −90° and 0°.
    assert!((-90.0..0.0).contains(&yaw), "look yaw {yaw}");
    let facing = app.session.component_to_world().rotation * glam::Vec3::Y;
    let facing_yaw = strider_host::world::direction_yaw(facing.x, facing.y);
    assert!(
        (facing_yaw - yaw).abs() < 5.0,
        "faces {facing_yaw}, aims {yaw}"
    );
    // W still walks along the camera's forward (+Y) while facing the aim.
    let p = app.session.component_to_world().translation;
    assert!(p.y > 50.0, "{p:?}");
}

/// The keyboard input of frame `k` of a walk that turns and stops.
fn turning_walk(k: u64) -> MoveInput {
    let direction = match k {
        0..90 => Vec2::Y,
        90..150 => Vec2::new(1.0, 1.0).normalize(),
        150..200 => Vec2::X,
        _ => Vec2::ZERO,
    };
    MoveInput {
        direction,
        speed: if k < 120 { 150.0 } else { 400.0 },
        facing: Facing::Velocity,
    }
}

#[test]
fn resuming_from_an_earlier_frame_replays_it_exactly_and_goes_on() {
    let mut session =
        Session::open(options(&PathBuf::from(GRAPHS).join("locomotion.ron"))).expect("loads");
    let lift = session
        .program()
        .variable_id("SplineLiftEnd")
        .expect("declared");
    // 4 s walking, turning, running and stopping, with a slider edit at frame 100.
    for k in 0..240 {
        if k == 100 {
            session
                .set_variable(lift, &Value::Float(45.0))
                .expect("a float");
        }
        session.input = turning_walk(k);
        session.step();
    }
    let original: Vec<_> = session
        .recorder()
        .iter()
        .map(|f| (f.meta, f.globals.clone(), f.slots.clone()))
        .collect();
    assert_eq!(original.len(), 240);

    // Resume from frame 145 (t 2.43 s): the state after it is the recorded one, bit for bit.
    session.resume_from(145).expect("resumes");
    assert!(
        !session.status().contains("differs"),
        "{}",
        session.status()
    );
    assert_eq!(session.frame(), 146);
    assert_eq!(session.time(), original[145].0.time);
    assert_eq!(
        session.recorder().len(),
        146,
        "the recorded future is dropped"
    );
    let mut slots = strider_inspector::recording::SlotImage::default();
    slots.copy_from(session.instance().slots());
    assert_eq!(slots, original[145].2, "every pin value and variable");
    let mut instance = session.instance().clone();
    assert_eq!(instance.pose_mut().globals(), original[145].1.as_slice());
    assert_eq!(session.instance().variable(lift), Value::Float(45.0));
    // The next frames, with the same input, are the ones recorded the first time.
    for k in 146..240 {
        session.input = turning_walk(k);
        session.step();
        let f = session.recorder().latest().expect("recorded");
        let (meta, globals, slots) = &original[k as usize];
        assert_eq!(f.meta.frame, meta.frame);
        assert_eq!(f.meta.to_world, meta.to_world, "frame {k}");
        assert_eq!(&f.globals, globals, "frame {k}");
        assert_eq!(&f.slots, slots, "frame {k}");
    }

    // Between the keyframe before the edit (frame 60) and the next (frame 120): the edit
    // is made again on the way, and the state is the recorded one.
    session.resume_from(110).expect("resumes");
    assert!(
        !session.status().contains("differs"),
        "{}",
        session.status()
    );
    slots.copy_from(session.instance().slots());
    assert_eq!(slots, original[110].2);
    assert_eq!(session.instance().variable(lift), Value::Float(45.0));

    // Back before the edit: the tunable is what it was then, and walking on differs from
    // the first time (the original walk turned at frame 150, this one keeps going).
    session.resume_from(90).expect("resumes");
    assert_eq!(session.instance().variable(lift), Value::Float(30.0));
    let mut instance = session.instance().clone();
    assert_eq!(instance.pose_mut().globals(), original[90].1.as_slice());
    for _ in 0..60 {
        session.input = MoveInput {
            direction: Vec2::NEG_X,
            speed: 150.0,
            facing: Facing::Velocity,
        };
        session.step();
    }
    let now = session.component_to_world().translation;
    let then = original[150].0.to_world.translation;
    assert!(now.x < then.x - 100.0, "{now:?} vs {then:?}");
}

#[test]
fn playing_from_a_scrubbed_frame_continues_from_it() {
    let mut harness = harness(options(&PathBuf::from(GRAPHS).join("locomotion.ron")));
    walk(&mut harness, Vec2::Y, 150.0, 239);
    let (index, frame) = {
        let app = harness.state_mut();
        app.playback.scrub_back(app.session.recorder(), 2.0);
        let index = app.playback.shown(app.session.recorder()).expect("a frame");
        let frame = app.session.recorder().get(index).expect("kept").meta;
        (index, frame)
    };
    assert!((118..=120).contains(&frame.frame), "{}", frame.frame);
    harness.run_steps(2);
    // Step from there: the frame after the one shown runs, the later ones are forgotten.
    harness.get_by_label("⏭ Step").click();
    harness.run_steps(2);
    let app = harness.state();
    assert!(app.controls.message.is_none(), "{:?}", app.controls.message);
    assert!(app.playback.cursor.is_none());
    assert_eq!(app.session.recorder().len(), index + 2);
    assert_eq!(app.session.frame(), frame.frame + 2);
    assert!(
        app.session
            .status()
            .starts_with(&format!("resumed from frame {} ", frame.frame)),
        "{}",
        app.session.status()
    );
}

#[test]
fn a_tunable_read_by_construction_reruns_it_and_keeps_the_state() {
    let dir = scratch_dir("tunable-construction");
    let graph = dir.join("derived.ron");
    std::fs::write(
        &graph,
        r#"Graph(
    version: 1,
    name: "derived",
    variables: {
        "Gain":    (type: Float, default: 2.0, tunable: (min: 0.0, max: 10.0)),
        "Other":   (type: Float, default: 1.0, tunable: (min: 0.0, max: 10.0)),
        "Doubled": (type: Float),
        "Count":   (type: Float),
    },
    nodes: {
        "twice": Multiply(a: var("Gain"), b: 2.0),
        "next":  Add(a: var("Count"), b: 1.0),
    },
    events: {
        construction: [ Set("Doubled", "twice") ],
        forward: [ Set("Count", "next") ],
    },
)
"#,
    )
    .expect("write");
    let mut harness = harness(options(&graph));
    harness.state_mut().advance(9);
    let get = |app: &InspectorApp, name: &str| {
        let id = app.session.program().variable_id(name).expect("declared");
        app.session.instance().variable(id)
    };
    assert_eq!(get(harness.state(), "Doubled"), Value::Float(4.0));
    // Type 5 into Gain's slider: construction gives Doubled = 5 · 2 = 10; Count keeps the
    // 10 frames counted (one when the app opened, 9 more).
    harness.state_mut().variables.filter = "Gain".to_string();
    harness.run_steps(2);
    harness.get_by_value("2.0").click();
    harness.run_steps(1);
    harness.event(egui::Event::Text("5".to_string()));
    harness.key_press(Key::Enter);
    harness.run_steps(2);
    assert_eq!(get(harness.state(), "Gain"), Value::Float(5.0));
    assert_eq!(get(harness.state(), "Doubled"), Value::Float(10.0));
    assert_eq!(get(harness.state(), "Count"), Value::Float(10.0));
    // A frame runs with it.
    harness.state_mut().advance(1);
    assert_eq!(get(harness.state(), "Count"), Value::Float(11.0));
    assert_eq!(get(harness.state(), "Doubled"), Value::Float(10.0));
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn dragged_nodes_are_saved_to_a_layout_file_beside_the_graph() {
    let dir = scratch_dir("layout");
    let graph = dir.join("bob.ron");
    let text = std::fs::read_to_string("tests/data/bob.ron").expect("read");
    std::fs::write(&graph, &text).expect("copy");
    let mut harness = harness(options(&graph));
    harness.run_steps(2);
    let layer = egui::LayerId::new(egui::Order::Background, egui::Id::new("strider-graph-view"));
    let (title, before, scale) = {
        let app = harness.state();
        let i = node_index(app, "offset");
        // Just above and left of the title: the node's frame (the title itself takes
        // clicks), which drags the node.
        let title =
            harness.get_by_label("offset: MakeVector").rect().left_top() - egui::vec2(3.0, 3.0);
        let t = harness
            .ctx
            .layer_transform_to_global(layer)
            .expect("a zoomed layer");
        (t * title, app.graph.body().positions[i], t.scaling)
    };
    // Drag the node's title 120 px right and 60 px down on screen.
    let delta = egui::vec2(120.0, 60.0);
    harness.hover_at(title);
    harness.run_steps(1);
    harness.drag_at(title);
    harness.run_steps(1);
    for k in 1..=4 {
        harness.hover_at(title + delta * (k as f32 / 4.0));
        harness.run_steps(1);
    }
    harness.drop_at(title + delta);
    harness.run_steps(2);
    let moved = harness
        .state()
        .graph
        .layout
        .position(strider_inspector::layout::TOP_LEVEL, "offset")
        .expect("the move is kept in the layout");
    let expected = before + delta / scale;
    assert!(
        (moved - expected).length() < 2.0,
        "{before:?} + {delta:?} / {scale} = {expected:?}, got {moved:?}"
    );
    assert!(harness.state().graph.layout_dirty);
    harness.get_by_label("Save layout*").click();
    harness.run_steps(2);
    let file = dir.join("bob.layout.ron");
    assert!(file.exists(), "written next to the graph");
    assert!(!harness.state().graph.layout_dirty);
    // The graph file is untouched; a new window shows the node where it was left.
    assert_eq!(std::fs::read_to_string(&graph).expect("read"), text);
    let again = crate::harness(options(&graph));
    let app = again.state();
    let i = node_index(app, "offset");
    assert_eq!(app.graph.body().positions[i], moved);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn pins_in_a_loop_say_they_show_the_last_iteration() {
    let mut harness = harness(options(&PathBuf::from(GRAPHS).join("locomotion.ron")));
    {
        let app = harness.state_mut();
        let program = std::sync::Arc::clone(app.session.program());
        let loaded = std::sync::Arc::clone(app.session.document());
        let body = strider_inspector::graph_view::build_body(&loaded, Some("SetupArray"));
        let in_loop = |label: &str| {
            body.nodes
                .iter()
                .find(|n| n.label() == label)
                .unwrap_or_else(|| panic!("{label}"))
                .in_loop
        };
        // `rest` and `elbow` read the loops' elements `foot` and `hand`; `feet` and `hands`
        // are computed once, before the loops.
        assert!(in_loop("rest") && in_loop("elbow"));
        assert!(!in_loop("feet") && !in_loop("hands"));
        // The Appends (one per per-foot or per-hand array) sit in the loop bodies; the
        // Resets before them do not.
        let appends: Vec<bool> = body
            .nodes
            .iter()
            .filter(|n| n.node_type == "Append")
            .map(|n| n.in_loop)
            .collect();
        assert!(appends.len() >= 12, "{} Appends", appends.len());
        assert!(appends.iter().all(|&a| a), "{appends:?}");
        assert!(
            body.nodes
                .iter()
                .filter(|n| n.node_type == "Reset")
                .all(|n| !n.in_loop)
        );
        assert!(
            app.graph
                .open_function_anywhere(&program, &loaded, "SetupArray")
        );
    }
    harness.run_steps(3);
    assert!(harness.state_mut().graph.select("rest"));
    harness.run_steps(2);
    harness.get_by_label("in a loop: the values of its last iteration");
    assert!(harness.state_mut().graph.select("feet"));
    harness.run_steps(2);
    assert!(
        harness
            .query_by_label("in a loop: the values of its last iteration")
            .is_none()
    );
}

#[test]
fn resuming_a_scenario_plays_the_same_frames_again() {
    let mut opts = options(&PathBuf::from(GRAPHS).join("locomotion.ron"));
    opts.scenario = Some(PathBuf::from(GRAPHS).join("scenarios/teleport.ron"));
    let mut session = Session::open(opts).expect("loads");
    for _ in 0..300 {
        session.step();
    }
    let original: Vec<_> = session
        .recorder()
        .iter()
        .map(|f| (f.meta, f.globals.clone()))
        .collect();
    session.resume_from(170).expect("resumes");
    assert!(
        !session.status().contains("differs"),
        "{}",
        session.status()
    );
    for (meta, globals) in &original[171..] {
        session.step();
        let f = session.recorder().latest().expect("recorded");
        assert_eq!(f.meta, *meta, "frame {}", meta.frame);
        assert_eq!(f.globals, *globals, "frame {}", meta.frame);
    }
}
