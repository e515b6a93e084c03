//! `strider bench GRAPH --skeleton SKEL --scenario SCEN`: how many characters running one
//! compiled graph fit in a frame, against the native baseline, from one thread to all cores.

use crate::alloc_count;
use crate::output;
use crate::setup::{Assignment, apply_assignments, instantiate, load, resolve_assignments};
use anyhow::{Context as _, anyhow, bail};
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use rayon::prelude::*;
use std::fmt::Write as _;
use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Arc;
use std::time::Instant;
use strider_graph::SkeletonFile;
use strider_host::scenario::{Scenario, Simulation};
use strider_host::world::World;
use strider_vm::native::NativeProgram;
use strider_vm::{BATCH, FrameInput, InputPose, Instance, Program};

/// A 60 Hz frame, in nanoseconds: the budget `characters_per_16ms` divides.
const FRAME_BUDGET_NS: f64 = 1e9 / 60.0;
/// Compiles timed for `compile_ms`.
const COMPILES: usize = 5;

/// Arguments of `strider bench`.
#[derive(Debug, clap::Args)]
#[command(
    about = "Measure a graph's cost per character and frame, crowds on threads, native ratio",
    long_about = "Measure what a graph costs per character and frame.\n\n\
        N instances of one compiled program each walk their own copy of the scenario's \
        input (60 Hz), offset in time so they are not in lock-step, in the scenario's world. \
        After a warm-up, the timed part runs F frames of all N characters, R times, at each \
        thread count from 1 to T (the instances split across threads with rayon; the program \
        is shared). Reported: the median time per character-frame with min and max over the \
        repetitions, characters per 16.6 ms frame, speed-up over one thread, heap \
        allocations per frame during the timed part, compile time (load + validate + \
        compile), and, for graphs with a native baseline (code generated ahead of time by \
        `strider native`, in crates/strider-native), the interpreter's time over the native \
        code's, measured in the same run, interleaved. See docs/performance.md."
)]
pub(crate) struct BenchArgs {
    /// Graph file to run (`Graph( ... )`, RON).
    #[arg(value_name = "GRAPH")]
    pub graph: PathBuf,

    /// Skeleton file (`Skeleton( ... )`, RON).
    #[arg(long, short = 's', value_name = "SKEL")]
    pub skeleton: PathBuf,

    /// Scenario file (`Scenario( ... )`, RON): the world and the input the characters walk.
    #[arg(long, value_name = "SCEN")]
    pub scenario: PathBuf,

    /// Number of characters (instances).
    #[arg(long, value_name = "N", default_value_t = 1000, value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    pub characters: u32,

    /// Timed frames per repetition (each frame runs every character once).
    #[arg(long, value_name = "F", default_value_t = 120, value_parser = clap::value_parser!(u32).range(1..=1_000_000))]
    pub frames: u32,

    /// Largest thread count; every count from 1 up to it is measured. Default: all cores.
    #[arg(long, value_name = "T", value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub threads: Option<u32>,

    /// Repetitions per thread count (the median is reported).
    #[arg(long, value_name = "R", default_value_t = 5, value_parser = clap::value_parser!(u32).range(1..=1000))]
    pub repetitions: u32,

    /// Frames every character runs before timing starts. Default: the whole scenario once,
    /// so that every character has been through every phase and its arrays have reached
    /// their working size.
    #[arg(long, value_name = "W")]
    pub warm_up: Option<u32>,

    /// Print one JSON object instead of the table.
    #[arg(long)]
    pub json: bool,

    /// Also profile the crowd as it runs (its first batch with a smaller `--batch`, one
    /// character with `--batch 1`) and print the 20 graph nodes with the most time per
    /// character-frame (needs a build with `--features profile`).
    #[arg(long)]
    pub profile: bool,

    /// Skip the native baseline even when the graph has one.
    #[arg(long)]
    pub no_native: bool,

    /// Characters the interpreter runs together through each instruction
    /// (`Instance::run_forward_batch`): 16 hands it each thread's share of the crowd, which
    /// it batches by path; fewer, consecutive chunks of that many; 1 runs each alone
    /// (`Instance::run_forward`). The native baseline always runs each character alone.
    #[arg(long, value_name = "B", default_value_t = 16, value_parser = clap::value_parser!(u32).range(1..=16))]
    pub batch: u32,

    /// Place the characters in the crowd in a scrambled order of their offsets into the
    /// scenario (a fixed permutation that puts neighbours in the crowd far apart in their
    /// cycles), as a game that spawns characters where and when it likes would, instead of
    /// in the order of their offsets (neighbours nearly in step).
    #[arg(long)]
    pub shuffle: bool,

    /// Run batches on the baseline x86-64 copy of the batch loop even where the processor
    /// has AVX2 (results are bit for bit the same; for measuring what AVX2 gives).
    #[arg(long)]
    pub baseline_code: bool,

    /// Set a graph variable before the first frame; repeatable (as in `strider run`).
    #[arg(long, value_name = "NAME=VALUE")]
    pub set: Vec<String>,

    /// Set tunable variables from an overrides file (a RON map `{ "Name": value, ... }`, as
    /// the inspector exports) before the first frame; `--set` wins for a variable both give.
    #[arg(long, value_name = "FILE")]
    pub overrides: Option<PathBuf>,
}

/// `--shuffle`'s scrambled order of `n` characters: character `i`'s place is `i` times a
/// stride near `n` divided by the golden ratio that shares no factor with `n` (so every
/// place is taken once), modulo `n`. Consecutive characters land about 0.38 × `n` places
/// apart.
fn scrambled(n: usize) -> impl Fn(usize) -> usize {
    fn gcd(a: usize, b: usize) -> usize {
        if b == 0 { a } else { gcd(b, a % b) }
    }
    let mut stride = (n as f64 * 0.618_034) as usize | 1;
    while gcd(stride, n) != 1 {
        stride += 1;
    }
    move |i| (i % n) * stride % n
}

/// Time per character-frame over the repetitions of one configuration, ns.
#[derive(Clone, Copy, Debug, serde::Serialize)]
struct Spread {
    median: f64,
    min: f64,
    max: f64,
}

impl Spread {
    fn of(samples: &mut [f64]) -> Spread {
        samples.sort_by(f64::total_cmp);
        let n = samples.len();
        let median = if n % 2 == 1 {
            samples[n / 2]
        } else {
            0.5 * (samples[n / 2 - 1] + samples[n / 2])
        };
        Spread {
            median,
            min: samples[0],
            max: samples[n - 1],
        }
    }
}

/// The figures of one thread count.
#[derive(Clone, Debug, serde::Serialize)]
struct Row {
    threads: u32,
    ns_per_character_frame: Spread,
    characters_per_16ms: f64,
    speedup: f64,
    native_ns_per_character_frame: Option<Spread>,
    native_ratio: Option<f64>,
}

/// The scenario's per-frame input, shared by all characters.
struct Track {
    inputs: Vec<(f32, strider_core::Transform)>,
}

/// One set of characters: instances and where each is in the track.
struct Crowd {
    instances: Vec<Instance>,
    offsets: Vec<usize>,
    /// Characters the interpreter runs together (1: each alone).
    batch: usize,
    /// The threads' shares of the crowd when it runs in full batches (one share on one
    /// thread).
    shares: Shares,
}

impl Crowd {
    /// The first `count` characters of the bench's crowd of `args.characters`: each an
    /// instance of `program` with the `assignments` applied, at its offset into `track`
    /// (the crowd's characters spread evenly over it, in the order of their offsets or, with
    /// `args.shuffle`, in [`scrambled`] order), run in batches of `args.batch`.
    fn first(
        count: usize,
        program: &Arc<Program>,
        skeleton: &SkeletonFile,
        args: &BenchArgs,
        assignments: &[Assignment],
        world: &World,
        track: &Track,
    ) -> anyhow::Result<Crowd> {
        let characters = (args.characters as usize).max(1);
        let mut instances = Vec::with_capacity(count);
        for _ in 0..count {
            let mut instance = instantiate(program, skeleton, &args.skeleton)?;
            apply(&mut instance, skeleton, assignments, world)?;
            instances.push(instance);
        }
        let place = scrambled(characters);
        Ok(Crowd {
            instances,
            offsets: (0..count)
                .map(|i| {
                    let place = if args.shuffle { place(i) } else { i };
                    place * track.inputs.len() / characters
                })
                .collect(),
            batch: args.batch as usize,
            shares: Shares::default(),
        })
    }

    /// Runs every character one frame (`frame` counts from the start of the run). The timed
    /// frames run without `debug`; a batch run with it leaves every slot as running each
    /// character alone would (without it, the slots of values that live only within a run
    /// keep what an earlier run left).
    fn run_frame(
        &mut self,
        track: &Track,
        world: &World,
        frame: usize,
        native: Option<&NativeProgram>,
        threads: u32,
        debug: bool,
    ) {
        let input = |offset: usize| {
            let (dt, to_world) = track.inputs[(frame + offset) % track.inputs.len()];
            FrameInput {
                dt,
                component_to_world: to_world,
                pose: InputPose::Rest,
            }
        };
        if native.is_none() && self.batch > 1 {
            let run = |(instances, offsets): (&mut [Instance], &[usize])| {
                Instance::run_forward_batch(instances, |k| input(offsets[k]), world, debug);
            };
            let (instances, offsets) = (&mut self.instances, &self.offsets);
            // A full batch: each thread's share of the crowd in one call (the whole crowd on
            // one thread), which picks the batches (characters whose last frames took one
            // path together), the shares balanced by the threads' times. A smaller one: the
            // crowd in batches of that size, in order.
            if self.batch == BATCH {
                self.shares.fit(threads as usize, instances.len());
                let Shares { bounds, nanos, .. } = &mut self.shares;
                run_shares(instances, offsets, bounds, nanos, &run);
                self.shares.balance();
            } else if threads == 1 {
                instances
                    .chunks_mut(self.batch)
                    .zip(offsets.chunks(self.batch))
                    .for_each(run);
            } else {
                instances
                    .par_chunks_mut(self.batch)
                    .zip(offsets.par_chunks(self.batch))
                    .for_each(run);
            }
            return;
        }
        let run = |(instance, offset): (&mut Instance, &usize)| {
            let input = input(*offset);
            match native {
                // Checked once before timing: cannot fail here.
                Some(native) => {
                    let _ = instance.run_forward_native(native, &input, world, debug);
                }
                None => instance.run_forward(&input, world, debug),
            }
        };
        if threads == 1 {
            self.instances.iter_mut().zip(&self.offsets).for_each(run);
        } else {
            self.instances
                .par_iter_mut()
                .zip(self.offsets.par_iter())
                .for_each(run);
        }
    }
}

/// The threads' shares of a batched crowd: contiguous runs of characters (in offset order,
/// so that a share's characters share their paths as the whole crowd's do), one per
/// thread, moved after every frame so that each takes the same time. Characters differ in
/// cost by where they are in the scenario (one standing costs less than one walking), so
/// equal halves leave one thread waiting for the other. Which thread runs a character
/// changes nothing it computes.
#[derive(Default)]
struct Shares {
    /// Share `k` is characters `bounds[k]..bounds[k + 1]`; `bounds[0] = 0`, the last is the
    /// crowd's size.
    bounds: Vec<usize>,
    /// How long each share took in the last frame, nanoseconds.
    nanos: Vec<f64>,
    /// The next frame's bounds while they are worked out.
    next: Vec<usize>,
}

impl Shares {
    /// Equal shares of a crowd of `n` for `threads` threads, unless the shares are for
    /// those already. Allocates only then (the bench's warm-up, and each pool's untimed
    /// frame, come before the frames it times).
    fn fit(&mut self, threads: usize, n: usize) {
        if self.nanos.len() == threads && self.bounds.last() == Some(&n) {
            return;
        }
        self.bounds = (0..=threads).map(|k| k * n / threads).collect();
        self.nanos = vec![0.0; threads];
        self.next = self.bounds.clone();
    }

    /// Moves each bound halfway to where the last frame's times put an equal share of the
    /// time: each share's characters taken to cost alike, its time spread evenly over them.
    /// Every share keeps at least one character when the crowd has one for each.
    fn balance(&mut self) {
        let threads = self.nanos.len();
        let n = self.bounds[threads];
        let total: f64 = self.nanos.iter().sum();
        if n < threads || !(total > 0.0 && total.is_finite()) {
            return;
        }
        for j in 1..threads {
            let goal = total * j as f64 / threads as f64;
            let mut before = 0.0;
            let mut at = self.bounds[j] as f64;
            for (k, &took) in self.nanos.iter().enumerate() {
                if before + took >= goal && took > 0.0 {
                    let (from, to) = (self.bounds[k] as f64, self.bounds[k + 1] as f64);
                    at = from + (goal - before) / took * (to - from);
                    break;
                }
                before += took;
            }
            let halfway = ((self.bounds[j] as f64 + at) / 2.0).round() as usize;
            self.next[j] = halfway.clamp(self.next[j - 1] + 1, n - (threads - j));
        }
        self.bounds.copy_from_slice(&self.next);
    }
}

/// Runs `run` on each share of `instances` (and their `offsets`) that `bounds` marks, each
/// on a thread of the current pool, and writes each share's time into `nanos`.
fn run_shares(
    instances: &mut [Instance],
    offsets: &[usize],
    bounds: &[usize],
    nanos: &mut [f64],
    run: &(impl Fn((&mut [Instance], &[usize])) + Sync),
) {
    if let [took] = nanos {
        let start = Instant::now();
        run((instances, offsets));
        *took = start.elapsed().as_nanos() as f64;
        return;
    }
    let half = nanos.len() / 2;
    let at = bounds[half] - bounds[0];
    let (first, second) = instances.split_at_mut(at);
    let (first_offsets, second_offsets) = offsets.split_at(at);
    let (first_nanos, second_nanos) = nanos.split_at_mut(half);
    rayon::join(
        || run_shares(first, first_offsets, &bounds[..=half], first_nanos, run),
        || run_shares(second, second_offsets, &bounds[half..], second_nanos, run),
    );
}

/// Runs `strider bench`.
pub(crate) fn run(args: &BenchArgs) -> anyhow::Result<ExitCode> {
    let (program, skeleton) = load(&args.graph, &args.skeleton)?;
    let compile_ms = compile_ms(args)?;
    let program = Arc::new(program);
    let assignments = resolve_assignments(&program, args.overrides.as_deref(), &args.set)?;
    let scenario = Scenario::load(&args.scenario).map_err(|e| anyhow!("{e}"))?;
    if args.profile && !cfg!(feature = "profile") {
        bail!(
            "--profile needs a build with profiling: cargo run --release --features profile -- bench ..."
        );
    }
    strider_vm::allow_avx2(!args.baseline_code);
    let batch_code = strider_vm::batch_code();
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get() as u32);
    let max_threads = args.threads.unwrap_or(cores);
    let native = if args.no_native {
        None
    } else {
        strider_native::find(&program)
    };

    let mut sim = Simulation::new(&scenario, 60);
    let world = sim.world().clone();
    let mut track = Track { inputs: Vec::new() };
    while let Some(frame) = sim.next_frame() {
        track.inputs.push((frame.dt, frame.component_to_world));
    }
    if track.inputs.is_empty() {
        bail!("{}: the scenario has no frames", args.scenario.display());
    }

    let n = args.characters as usize;
    let make_crowd = || Crowd::first(n, &program, &skeleton, args, &assignments, &world, &track);
    let mut crowd = make_crowd()?;
    let mut native_crowd = match native {
        Some(_) => Some(make_crowd()?),
        None => None,
    };

    let bar = progress_bar(args, max_threads);
    let pools: Vec<rayon::ThreadPool> = (1..=max_threads)
        .map(|t| {
            rayon::ThreadPoolBuilder::new()
                .num_threads(t as usize)
                // As much stack as the main thread has.
                .stack_size(8 << 20)
                .build()
                .context("cannot start the worker threads")
        })
        .collect::<anyhow::Result<_>>()?;
    // A pool's threads start on their own time, and each allocates its job queue as it
    // starts: wait until every worker of every pool has run a job, so none is still starting
    // while frames are counted (the one-thread row runs outside the pools, alongside them).
    // That job makes each worker's batch scratch too: the scheduler may give a worker its
    // first share of the crowd in a counted frame.
    for pool in &pools {
        pool.broadcast(|_| Instance::reserve_batch_scratch(&program, n));
    }

    // Warm-up: both crowds run the same frames, so they stay in step.
    let warm_up = args.warm_up.unwrap_or(track.inputs.len() as u32);
    let mut frame = 0usize;
    bar.set_message("warm-up");
    for _ in 0..warm_up {
        crowd.run_frame(&track, &world, frame, None, 1, false);
        if let (Some(c), Some(code)) = (native_crowd.as_mut(), native) {
            c.run_frame(&track, &world, frame, Some(code), 1, false);
        }
        frame += 1;
    }

    let mut rows = Vec::new();
    let mut allocations: Option<u64> = Some(0);
    let mut timed_frames = 0u64;
    let per_rep = f64::from(args.frames) * n as f64;
    for (t, pool) in (1..=max_threads).zip(&pools) {
        bar.set_message(format!("{t} thread{}", if t == 1 { "" } else { "s" }));
        let mut measure = || {
            let mut interp = Vec::new();
            let mut native_times = Vec::new();
            // One untimed frame on these threads first (their first jobs set up per-thread
            // state of the scheduler).
            crowd.run_frame(&track, &world, frame, None, t, false);
            if let (Some(c), Some(code)) = (native_crowd.as_mut(), native) {
                c.run_frame(&track, &world, frame, Some(code), t, false);
            }
            frame += 1;
            for rep in 0..args.repetitions {
                // Interleaved, alternating which goes first.
                let mut order = [false, true];
                if rep % 2 == 1 {
                    order.reverse();
                }
                for is_native in order {
                    let (c, code) = match (is_native, native_crowd.as_mut(), native) {
                        (false, _, _) => (&mut crowd, None),
                        (true, Some(c), Some(code)) => (c, Some(code)),
                        (true, _, _) => continue,
                    };
                    let start_frame = frame;
                    let (elapsed, counted) = alloc_count::count(|| {
                        let start = Instant::now();
                        for f in 0..args.frames as usize {
                            c.run_frame(&track, &world, start_frame + f, code, t, false);
                        }
                        start.elapsed()
                    });
                    allocations = allocations.zip(counted).map(|(a, b)| a + b);
                    timed_frames += u64::from(args.frames);
                    let ns = elapsed.as_nanos() as f64 / per_rep;
                    if is_native {
                        native_times.push(ns);
                    } else {
                        interp.push(ns);
                    }
                }
                frame += args.frames as usize;
                bar.inc(1);
            }
            (interp, native_times)
        };
        // One thread runs here, without the pool; more run inside the pool (entered once per
        // thread count, outside the counted spans: entering it queues a job, which may
        // allocate).
        let (mut interp, mut native_times) = if t == 1 {
            measure()
        } else {
            pool.install(measure)
        };
        let spread = Spread::of(&mut interp);
        let native_spread = (!native_times.is_empty()).then(|| Spread::of(&mut native_times));
        rows.push(Row {
            threads: t,
            ns_per_character_frame: spread,
            characters_per_16ms: FRAME_BUDGET_NS / spread.median,
            speedup: 0.0,
            native_ns_per_character_frame: native_spread,
            native_ratio: native_spread.map(|s| spread.median / s.median),
        });
    }
    bar.finish_and_clear();
    let single = rows[0].ns_per_character_frame.median;
    for row in &mut rows {
        row.speedup = single / row.ns_per_character_frame.median;
    }
    let allocations_per_frame = allocations.map(|a| a as f64 / timed_frames.max(1) as f64);
    // The largest instance once warmed up (their buffers no longer grow).
    // Measured before the check frame below, whose debug drawing fills the debug buffer
    // (the timed frames run without).
    let instance_bytes = crowd
        .instances
        .iter()
        .map(Instance::memory_bytes)
        .max()
        .unwrap_or(0);
    // One more frame of both crowds, with debug, so that a batch brings back every slot
    // (see `Crowd::run_frame`); then every slot and bone must be the same.
    if let (Some(c), Some(code)) = (native_crowd.as_mut(), native) {
        crowd.run_frame(&track, &world, frame, None, 1, true);
        c.run_frame(&track, &world, frame, Some(code), 1, true);
    }
    let identical = match &native_crowd {
        Some(c) => Some(
            crowd
                .instances
                .iter()
                .zip(&c.instances)
                .all(|(a, b)| same_state(a, b)),
        ),
        None => None,
    };
    let profile = if args.profile {
        Some(profile_top(
            &program,
            &skeleton,
            args,
            &assignments,
            &track,
            &world,
            warm_up as usize,
        )?)
    } else {
        None
    };

    let headline = rows
        .last()
        .cloned()
        .ok_or_else(|| anyhow!("no thread count"))?;
    if args.json {
        let value = serde_json::json!({
            "graph": program.name(),
            "scenario": scenario.name,
            "characters": n,
            "frames": args.frames,
            "repetitions": args.repetitions,
            "warm_up_frames": warm_up,
            "threads": max_threads,
            "batch": args.batch,
            "shuffled": args.shuffle,
            "batch_code": batch_code.name(),
            "cores": cores,
            "ns_per_character_frame": headline.ns_per_character_frame,
            "characters_per_16ms": headline.characters_per_16ms,
            "allocations_per_frame": allocations_per_frame,
            "instance_bytes": instance_bytes,
            "compile_ms": compile_ms,
            "native_ratio": headline.native_ratio,
            "native_identical": identical,
            "scaling": rows,
            "profile": profile.as_ref().map(|p| &p.json),
        });
        output::print_stdout(&format!("{value}\n"))?;
    } else {
        let mut text = String::new();
        let _ = writeln!(
            text,
            "graph       {} ({})\nscenario    {} ({}), 60 Hz input, characters offset in time{}\n\
             workload    {n} characters x {} frames x {} repetitions per thread count, after {} warm-up frames\n\
             batch       {} characters through each instruction together (native: each alone), {} code\n\
             machine     {cores} cores\n\
             compile     {compile_ms:.2} ms (load + validate + compile, median of {COMPILES})\n",
            program.name(),
            args.graph.display(),
            scenario.name,
            args.scenario.display(),
            if args.shuffle {
                ", in scrambled order"
            } else {
                ""
            },
            args.frames,
            args.repetitions,
            warm_up,
            args.batch,
            batch_code.name(),
        );
        let _ = writeln!(
            text,
            "threads   ns/character-frame [min, max]   characters/16.6 ms   speed-up   native ns [min, max]     native ratio"
        );
        for r in &rows {
            let s = r.ns_per_character_frame;
            let native = match (r.native_ns_per_character_frame, r.native_ratio) {
                (Some(n), Some(ratio)) => format!(
                    "{:>7.0} [{:.0}, {:.0}]   {ratio:>6.2}x",
                    n.median, n.min, n.max
                ),
                _ => "      -".to_string(),
            };
            let _ = writeln!(
                text,
                "{:>7}   {:>8.0} [{:.0}, {:.0}]   {:>18.0}   {:>7.2}x   {native}",
                r.threads, s.median, s.min, s.max, r.characters_per_16ms, r.speedup
            );
        }
        let _ = writeln!(text);
        match allocations_per_frame {
            Some(a) => {
                let _ = writeln!(
                    text,
                    "allocations {a} per frame ({} in {timed_frames} timed frames of {n} characters)",
                    allocations.unwrap_or(0)
                );
            }
            None => {
                let _ = writeln!(text, "allocations not counted (no counting allocator)");
            }
        }
        let _ = writeln!(
            text,
            "memory      {instance_bytes} bytes per instance (slots, pose, debug buffer; the program and skeleton are shared)"
        );
        match (native, identical) {
            (Some(code), Some(same)) => {
                let _ = writeln!(
                    text,
                    "native      code generated from `{}`; outputs {} the interpreter's",
                    code.name,
                    if same {
                        "bit-identical to"
                    } else {
                        "DIFFERENT from"
                    }
                );
            }
            _ if args.no_native => {}
            _ => {
                let _ = writeln!(
                    text,
                    "native      no baseline for this program (generate one with `strider native`)"
                );
            }
        }
        if let Some(p) = &profile {
            let _ = write!(text, "\n{}", p.table);
        }
        output::print_stdout(&text)?;
    }
    Ok(ExitCode::SUCCESS)
}

/// Load + validate + compile of the graph, median of [`COMPILES`] runs, ms.
fn compile_ms(args: &BenchArgs) -> anyhow::Result<f64> {
    let mut times = Vec::with_capacity(COMPILES);
    for _ in 0..COMPILES {
        let start = Instant::now();
        let compiled = strider_compiler::compile_file(&args.graph);
        times.push(start.elapsed().as_secs_f64() * 1e3);
        if compiled.is_err() {
            bail!("{} no longer compiles", args.graph.display());
        }
    }
    Ok(Spread::of(&mut times).median)
}

fn apply(
    instance: &mut Instance,
    skeleton: &SkeletonFile,
    assignments: &[Assignment],
    world: &World,
) -> anyhow::Result<()> {
    if !assignments.is_empty() {
        apply_assignments(instance, skeleton, assignments, world)?;
    }
    Ok(())
}

/// Whether two instances hold bit-identical slots and poses.
fn same_state(a: &Instance, b: &Instance) -> bool {
    let (pa, pb) = (a.pose().locals(), b.pose().locals());
    pa.len() == pb.len()
        && pa.iter().zip(pb).all(|(x, y)| x.bit_eq(y))
        && a.slots().bit_eq(b.slots())
}

fn progress_bar(args: &BenchArgs, max_threads: u32) -> ProgressBar {
    let bar = ProgressBar::new(u64::from(max_threads) * u64::from(args.repetitions));
    bar.set_style(
        ProgressStyle::with_template("{msg:>12} [{bar:40}] {pos}/{len} repetitions ({eta})")
            .unwrap_or_else(|_| ProgressStyle::default_bar())
            .progress_chars("=> "),
    );
    if args.json {
        bar.set_draw_target(ProgressDrawTarget::hidden());
    }
    bar
}

/// The profiler's top 20, as a table and as JSON.
struct ProfileTop {
    table: String,
    json: serde_json::Value,
}

#[cfg(feature = "profile")]
fn profile_top(
    program: &Arc<Program>,
    skeleton: &SkeletonFile,
    args: &BenchArgs,
    assignments: &[Assignment],
    track: &Track,
    world: &World,
    warm_up: usize,
) -> anyhow::Result<ProfileTop> {
    // The crowd as the bench runs it, batched by path (with a smaller `--batch`, its first
    // batch; with `--batch 1`, its first character alone), each character at its offset
    // into the scenario.
    let k = if args.batch as usize == BATCH {
        args.characters as usize
    } else {
        (args.batch as usize).min(args.characters as usize)
    }
    .max(1);
    let mut crowd = Crowd::first(k, program, skeleton, args, assignments, world, track)?;
    for f in 0..warm_up {
        crowd.run_frame(track, world, f, None, 1, false);
    }
    for instance in &mut crowd.instances {
        instance.set_profiling(true);
    }
    let frames = track.inputs.len().max(args.frames as usize);
    for f in 0..frames {
        crowd.run_frame(track, world, warm_up + f, None, 1, false);
    }
    // The characters' profiles summed, per instruction, then per node.
    let mut summed = vec![strider_vm::InstrProfile::default(); program.code().len()];
    for instance in &crowd.instances {
        for (sum, p) in summed.iter_mut().zip(instance.profile()) {
            sum.nanos += p.nanos;
            sum.count += p.count;
        }
    }
    let nodes = strider_vm::profile_by_node(program, &summed);
    let total: u64 = nodes.iter().map(|n| n.nanos).sum();
    let character_frames = (k * frames) as f64;
    let per_frame = |x: u64| x as f64 / character_frames;
    let how = if k > 1 {
        format!("{k} characters batched")
    } else {
        "one character".to_string()
    };
    let mut table = format!(
        "profile     {how}, {frames} frames, {:.0} ns per character-frame profiled (the timer inflates cheap nodes; see docs/performance.md)\n\
          share   ns/frame   runs/f  node\n",
        per_frame(total)
    );
    let mut json = Vec::new();
    for node in nodes.iter().take(20) {
        let what = node
            .origin(program)
            .map_or_else(|| "(no origin)".to_string(), ToString::to_string);
        let share = 100.0 * node.nanos as f64 / total.max(1) as f64;
        let _ = writeln!(
            table,
            "{share:>6.1}% {:>10.1} {:>8.1}  {what}",
            per_frame(node.nanos),
            per_frame(node.runs),
        );
        json.push(serde_json::json!({
            "node": what,
            "share_percent": share,
            "ns_per_frame": per_frame(node.nanos),
            "runs_per_frame": per_frame(node.runs),
        }));
    }
    Ok(ProfileTop {
        table,
        json: json.into(),
    })
}

#[cfg(not(feature = "profile"))]
fn profile_top(
    _: &Arc<Program>,
    _: &SkeletonFile,
    _: &BenchArgs,
    _: &[Assignment],
    _: &Track,
    _: &World,
    _: usize,
) -> anyhow::Result<ProfileTop> {
    bail!(
        "--profile needs a build with profiling: cargo run --release --features profile -- bench ..."
    )
}

#[cfg(test)]
mod tests {
    use super::{Shares, scrambled};

    /// Shares after `fit` and one `balance` with the given times.
    fn balanced(threads: usize, n: usize, nanos: &[f64]) -> Vec<usize> {
        let mut shares = Shares::default();
        shares.fit(threads, n);
        shares.nanos.copy_from_slice(nanos);
        shares.balance();
        shares.bounds
    }

    /// A share that took longer gives characters to the next: each bound moves halfway to
    /// where the times, spread evenly over each share's characters, split them equally.
    #[test]
    fn the_threads_shares_move_toward_equal_times() {
        // Equal halves of 100, the first 3 times as slow: half the time, 2 of 4, lies 2/3
        // of the way into the first share, at 33.3; halfway from 50 is 41.67.
        assert_eq!(balanced(2, 100, &[3.0, 1.0]), [0, 42, 100]);
        // The other way round: 50 + 16.67 / 2 = 58.33.
        assert_eq!(balanced(2, 100, &[1.0, 3.0]), [0, 58, 100]);
        // Balanced already: nothing moves.
        assert_eq!(balanced(2, 100, &[2.0, 2.0]), [0, 50, 100]);
        // Three shares of 30 (10 each), times 1, 1, 4 of 6: the first bound's goal (2) is
        // the end of share 1 (20, halfway from 10: 15), the second's (4) half-way through
        // share 2 (25, halfway from 20: 22.5, rounded to 23).
        assert_eq!(balanced(3, 30, &[1.0, 1.0, 4.0]), [0, 15, 23, 30]);
        // Every share keeps a character, however slow its neighbour.
        assert_eq!(balanced(3, 3, &[100.0, 0.0, 0.0]), [0, 1, 2, 3]);
        // No usable times (none yet, or not finite): the shares stay equal.
        assert_eq!(balanced(2, 100, &[0.0, 0.0]), [0, 50, 100]);
        assert_eq!(balanced(2, 100, &[f64::NAN, 1.0]), [0, 50, 100]);
        assert_eq!(balanced(2, 100, &[f64::INFINITY, 1.0]), [0, 50, 100]);
        // Fewer characters than threads: the empty shares stay as they are.
        assert_eq!(balanced(3, 2, &[1.0, 1.0, 0.0]), [0, 0, 1, 2]);
    }

    /// `--shuffle` takes every place once, for crowds whose size shares factors with the
    /// stride's first guess too, and puts neighbours apart.
    #[test]
    fn the_scrambled_order_is_a_permutation_that_parts_neighbours() {
        for n in (1..=64).chain([100, 618, 1000, 1024, 7919, 10_000]) {
            let mut taken = vec![false; n];
            let scrambled = scrambled(n);
            for i in 0..n {
                let place = scrambled(i);
                assert!(place < n && !taken[place], "n = {n}: place {place} twice");
                taken[place] = true;
            }
        }
        let scrambled = scrambled(1000);
        assert_eq!(scrambled(0), 0);
        let apart = scrambled(1).abs_diff(scrambled(0));
        assert!(
            (300..=700).contains(&apart),
            "neighbours {apart} places apart"
        );
    }
}
