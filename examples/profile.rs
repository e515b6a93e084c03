//! Per-node profile of a graph: runs a number of forward frames on the mannequin in an
//! empty world with profiling on, then prints the 20 most expensive graph nodes and steps
//! (what `strider bench --profile --batch 1` prints for one character). Needs the
//! `profile` feature:
//!
//! ```text
//! cargo run --release --features profile --example profile -- [GRAPH] [FRAMES]
//! ```
//!
//! `GRAPH` defaults to `graphs/foot_ik.ron`, `FRAMES` to 10000. See docs/performance.md.

use std::error::Error;
use std::path::Path;
use std::sync::Arc;
use strider::{EmptyWorld, FrameInput, Instance};

fn main() -> Result<(), Box<dyn Error>> {
    let mut args = std::env::args().skip(1);
    let graph = args
        .next()
        .unwrap_or_else(|| "graphs/foot_ik.ron".to_string());
    let frames: u64 = match args.next() {
        Some(n) => n.parse()?,
        None => 10_000,
    };
    let program = match strider::compile_file(Path::new(&graph)) {
        Ok(p) => Arc::new(p),
        Err(d) => {
            for e in &d {
                eprintln!("{e}");
            }
            return Err(format!("{graph} does not compile").into());
        }
    };
    let skeleton = strider::load_skeleton(Path::new("graphs/skeletons/mannequin.ron"))
        .map_err(|_| "graphs/skeletons/mannequin.ron does not load")?
        .skeleton;
    let mut inst = Instance::new(Arc::clone(&program), skeleton)?;
    let input = FrameInput {
        dt: 1.0 / 60.0,
        ..Default::default()
    };
    for _ in 0..60 {
        inst.run_forward(&input, &EmptyWorld, false);
    }
    inst.set_profiling(true);
    for _ in 0..frames {
        inst.run_forward(&input, &EmptyWorld, false);
    }
    let nodes = inst.profile_by_node();
    let total: u64 = nodes.iter().map(|n| n.nanos).sum();
    println!(
        "{graph}: {frames} frames, {:.0} ns per frame (profiled), {} instructions",
        total as f64 / frames as f64,
        program.code().len()
    );
    println!("{:>6} {:>10} {:>8}  node", "share", "ns/frame", "runs/f");
    for n in nodes.iter().take(20) {
        let what = n
            .origin(&program)
            .map_or_else(|| "(no origin)".to_string(), ToString::to_string);
        println!(
            "{:>5.1}% {:>10.1} {:>8.1}  {what}",
            100.0 * n.nanos as f64 / total.max(1) as f64,
            n.nanos as f64 / frames as f64,
            n.runs as f64 / frames as f64,
        );
    }
    Ok(())
}
