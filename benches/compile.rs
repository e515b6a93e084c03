//! Load + validate + compile of every shipped graph: `strider::compile_file` (read the file
//! and its imports, parse, check, generate code). `graphs/locomotion.ron` is included when
//! it exists and compiles.
//!
//! Run: `cargo bench --bench compile` (see docs/performance.md).

use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::path::{Path, PathBuf};

/// Every `.ron` graph under `graphs/` (not the skeletons), sorted.
fn shipped_graphs() -> Vec<PathBuf> {
    let mut out = Vec::new();
    for dir in ["graphs", "graphs/examples"] {
        let Ok(entries) = std::fs::read_dir(dir) else {
            continue;
        };
        for e in entries.flatten() {
            let path = e.path();
            if path.extension().is_some_and(|x| x == "ron") {
                out.push(path);
            }
        }
    }
    out.sort();
    out
}

fn compile(c: &mut Criterion) {
    let mut g = c.benchmark_group("compile");
    for path in shipped_graphs() {
        if let Err(d) = strider::compile_file(&path) {
            eprintln!(
                "note: {} does not compile ({} diagnostics); skipped",
                path.display(),
                d.len()
            );
            continue;
        }
        let name = path
            .strip_prefix("graphs")
            .unwrap_or(&path)
            .with_extension("")
            .to_string_lossy()
            .into_owned();
        g.bench_function(name.as_str(), |b| {
            b.iter(|| strider::compile_file(black_box(Path::new(&path))));
        });
    }
    g.finish();
}

criterion_group!(benches, compile);
criterion_main!(benches);
