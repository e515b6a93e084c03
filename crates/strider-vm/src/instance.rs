//! [`Instance`]: one character's state for a shared [`Program`].

use crate::exec::{self, Ctx};
use crate::lanes::SameBits;
use crate::native::NativeProgram;
use crate::program::{BoneSlot, Program, VariableId};
use crate::slots::Slots;
use glam::Affine3A;
use std::fmt;
use std::sync::Arc;
use strider_core::{DebugDraw, EmptyWorld, Pose, Skeleton, Transform, WorldQuery};
use strider_nodes::{Value, ValueType};

/// The pose an instance starts each frame from.
#[derive(Clone, Copy, Debug, Default)]
pub enum InputPose<'a> {
    /// Start from the skeleton's rest pose (a pure procedural rig).
    #[default]
    Rest,
    /// Keep last frame's output pose.
    Previous,
    /// Start from these local transforms, in the skeleton's storage order (an animation
    /// the rig post-processes). Missing entries keep the previous value.
    Locals(&'a [Transform]),
}

/// What the host gives each frame.
#[derive(Clone, Copy, Debug)]
pub struct FrameInput<'a> {
    /// Seconds since the previous frame. NaN, infinite or negative values are treated as 0.
    pub dt: f32,
    /// Where the host placed the character: component (rig) space to world space, cm.
    /// A transform with NaN or infinity is ignored (last frame's is kept).
    pub component_to_world: Transform,
    /// The pose to start from.
    pub pose: InputPose<'a>,
}

impl Default for FrameInput<'_> {
    fn default() -> Self {
        Self {
            dt: 0.0,
            component_to_world: Transform::IDENTITY,
            pose: InputPose::Rest,
        }
    }
}

/// A bone the graph names that the skeleton lacks.
#[derive(Clone, Debug, PartialEq)]
pub struct MissingBone {
    /// The name in the graph.
    pub name: String,
    /// `file:line:col` and node/pin of the reference.
    pub location: String,
    /// The closest bone name of the skeleton.
    pub suggestion: Option<String>,
}

/// An instance could not be created for this skeleton.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum InstantiateError {
    /// Bones named in the graph are missing from the skeleton (each reference once).
    #[error("{}", fmt_missing(.skeleton, .missing))]
    MissingBones {
        /// The skeleton's name for the message; empty when the instance does not know it
        /// (a host that does may fill it in).
        skeleton: String,
        /// Every missing reference.
        missing: Vec<MissingBone>,
    },
}

fn fmt_missing(skeleton: &str, missing: &[MissingBone]) -> String {
    let mut out = String::new();
    for (i, m) in missing.iter().enumerate() {
        if i > 0 {
            out.push('\n');
        }
        out.push_str(&format!("{}: error: unknown bone `{}`", m.location, m.name));
        if !skeleton.is_empty() {
            out.push_str(&format!(" in skeleton `{skeleton}`"));
        }
        if let Some(s) = &m.suggestion {
            out.push_str(&format!("\n  hint: did you mean `{s}`?"));
        }
    }
    out
}

/// A variable could not be set.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
pub enum VariableError {
    /// The value's type is not the variable's.
    #[error("variable `{name}` is {expected}, not {found}")]
    TypeMismatch {
        /// The variable.
        name: String,
        /// Its type.
        expected: ValueType,
        /// The value's type.
        found: ValueType,
    },
    /// A bone value names a bone the skeleton lacks.
    #[error("variable `{name}`: unknown bone `{bone}`")]
    UnknownBone {
        /// The variable.
        name: String,
        /// The bone name.
        bone: String,
    },
}

/// One character running a program: all mutable state, allocated at creation.
///
/// After the first frames (arrays and debug buffers reach their working size),
/// [`Instance::run_forward`] performs no heap allocation.
#[derive(Clone, Debug)]
pub struct Instance {
    program: Arc<Program>,
    slots: Slots,
    pose: Pose,
    debug: DebugDraw,
    to_world: Transform,
    /// Runs so far (construction and frames); stateful nodes use it to advance once per run.
    runs: i32,
    /// Fingerprint of the native code last checked against the program
    /// ([`Instance::run_forward_native`]).
    native_checked: Option<u64>,
    /// How many of the slots that no instruction writes (constants, variables only the host
    /// sets) hold other bits than the program's initial value there: 0 while the host has
    /// set none of those variables to another value (or has set them back). A batch of
    /// instances at 0 takes those slots from the program, once for as long as the thread's
    /// lanes run this program.
    unwritten_changed: u32,
    /// The path key of the last run ([`Ctx::path`](crate::exec::Ctx)): which jumps it took.
    /// `Instance::run_forward_batch` batches instances with equal keys together.
    path: u64,
    /// The jump sites of the last run ([`Instance::jump_sites`]).
    taken: u64,
    /// Whether runs accumulate into `profile`.
    #[cfg(feature = "profile")]
    profiling: bool,
    /// Per instruction: time and runs, allocated once with the instance.
    #[cfg(feature = "profile")]
    profile: Vec<crate::profile::InstrProfile>,
}

impl Instance {
    /// Creates an instance on `skeleton`: resolves the bone names of the graph, starts
    /// from the rest pose and runs the `construction` event (with no world geometry).
    ///
    /// # Errors
    /// [`InstantiateError::MissingBones`] listing every bone the graph names that the
    /// skeleton lacks, with where the graph names it.
    pub fn new(program: Arc<Program>, skeleton: Arc<Skeleton>) -> Result<Self, InstantiateError> {
        let slots = program.initial.clone();
        #[cfg(feature = "profile")]
        let profile = vec![crate::profile::InstrProfile::default(); program.code.len()];
        let mut instance = Self {
            program,
            slots,
            pose: Pose::new(skeleton),
            debug: DebugDraw::new(false),
            to_world: Transform::IDENTITY,
            runs: 0,
            native_checked: None,
            unwritten_changed: 0,
            path: 0,
            taken: 0,
            #[cfg(feature = "profile")]
            profiling: false,
            #[cfg(feature = "profile")]
            profile,
        };
        instance.resolve_bones()?;
        instance.run_construction(&EmptyWorld);
        Ok(instance)
    }

    /// Moves the instance to another skeleton: resolves bones again, resets the pose and
    /// every variable that is not tunable, and re-runs `construction`. Tunable values are
    /// kept. On error the instance is unchanged.
    ///
    /// # Errors
    /// As [`Instance::new`].
    pub fn rebind(
        &mut self,
        skeleton: Arc<Skeleton>,
        world: &dyn WorldQuery,
    ) -> Result<(), InstantiateError> {
        let mut next = Self {
            program: Arc::clone(&self.program),
            slots: self.program.initial.clone(),
            pose: Pose::new(skeleton),
            debug: DebugDraw::new(false),
            to_world: self.to_world,
            runs: 0,
            native_checked: self.native_checked,
            // Counted once the tunables are copied, below.
            unwritten_changed: 0,
            path: 0,
            taken: 0,
            #[cfg(feature = "profile")]
            profiling: self.profiling,
            #[cfg(feature = "profile")]
            profile: Vec::new(),
        };
        next.resolve_bones()?;
        for v in self
            .program
            .variables
            .iter()
            .filter(|v| v.tunable.is_some())
        {
            copy_slot(&self.slots, &mut next.slots, v.ty, v.slot);
            next.unwritten_changed += u32::from(next.unwritten_differs(v.ty, v.slot));
        }
        next.debug = std::mem::take(&mut self.debug);
        #[cfg(feature = "profile")]
        {
            next.profile = std::mem::take(&mut self.profile);
        }
        *self = next;
        self.run_construction(world);
        Ok(())
    }

    fn resolve_bones(&mut self) -> Result<(), InstantiateError> {
        let skeleton = Arc::clone(self.pose.skeleton());
        let mut missing = Vec::new();
        for lit in &self.program.bones {
            match skeleton.find(&lit.name) {
                Some(b) => match lit.slot {
                    BoneSlot::Scalar(s) => self.slots.bones[s as usize] = b.0 as i32,
                    BoneSlot::ArrayElement { slot, index } => {
                        self.slots.bone_arrays[slot as usize][index as usize] = b.0 as i32;
                    }
                },
                None => {
                    let seen = missing
                        .iter()
                        .any(|m: &MissingBone| m.name == lit.name && m.location == lit.location);
                    if !seen {
                        missing.push(MissingBone {
                            name: lit.name.clone(),
                            location: lit.location.clone(),
                            suggestion: skeleton.suggest(&lit.name),
                        });
                    }
                }
            }
        }
        if missing.is_empty() {
            Ok(())
        } else {
            Err(InstantiateError::MissingBones {
                skeleton: String::new(),
                missing,
            })
        }
    }

    /// Switches per-instruction profiling on or off (off at creation, so construction run
    /// by [`Instance::new`] is not profiled). While on, every run of either event adds each
    /// executed instruction's time and one count to [`Instance::profile`]; nothing is
    /// allocated. Only with the `profile` feature of `strider-vm`.
    #[cfg(feature = "profile")]
    pub fn set_profiling(&mut self, on: bool) {
        self.profiling = on;
    }

    /// Whether profiling is on (always `false` without the `profile` feature).
    #[must_use]
    pub fn is_profiling(&self) -> bool {
        #[cfg(feature = "profile")]
        return self.profiling;
        #[cfg(not(feature = "profile"))]
        false
    }

    /// The accumulated profile, one entry per instruction of the program (indexed like
    /// [`Program::code`]), since creation or the last [`Instance::reset_profile`]. Group it
    /// per graph node with [`Instance::profile_by_node`]. Run in a batch
    /// ([`Instance::run_forward_batch`]), an instruction's time is its dispatch's, shared
    /// equally among the batch's members at it. Only with the `profile` feature.
    #[cfg(feature = "profile")]
    #[must_use]
    pub fn profile(&self) -> &[crate::profile::InstrProfile] {
        &self.profile
    }

    /// Zeroes the accumulated profile (keeps its memory; profiling stays on or off).
    #[cfg(feature = "profile")]
    pub fn reset_profile(&mut self) {
        self.profile.fill(crate::profile::InstrProfile::default());
    }

    /// The accumulated profile grouped per graph node or step, most expensive first (see
    /// [`crate::profile_by_node`]). Allocates: for tools. Only with the `profile` feature.
    #[cfg(feature = "profile")]
    #[must_use]
    pub fn profile_by_node(&self) -> Vec<crate::profile::NodeProfile> {
        crate::profile::profile_by_node(&self.program, &self.profile)
    }

    /// The program this instance runs.
    #[must_use]
    pub fn program(&self) -> &Arc<Program> {
        &self.program
    }

    /// Runs the `construction` event again on the rest pose (dt = 0).
    pub fn run_construction(&mut self, world: &dyn WorldQuery) {
        self.pose.reset_to_rest();
        self.debug.clear();
        let entry = self.program.construction;
        self.run_event(Body::Program(entry), world, 0.0);
    }

    /// Runs one frame of the `forward` event.
    ///
    /// `debug` turns debug drawing on for this frame; the primitives are then available
    /// from [`Instance::debug_draw`] until the next frame.
    pub fn run_forward(&mut self, input: &FrameInput<'_>, world: &dyn WorldQuery, debug: bool) {
        let dt = self.begin_frame(input, debug);
        let entry = self.program.forward;
        self.run_event(Body::Program(entry), world, dt);
    }

    /// Runs one frame of the `forward` event with code generated ahead of time from this
    /// instance's program ([`crate::native`]) instead of the interpreter: the native
    /// baseline. Same inputs, same effects, bit-identical results.
    ///
    /// # Errors
    /// [`NativeMismatch`] (and nothing runs) when `native` was generated from another
    /// program. The check compares the program's fingerprint (computed once per program,
    /// O(program size), the first time any instance asks) the first time a given `native`
    /// is used with this instance, then nothing.
    pub fn run_forward_native(
        &mut self,
        native: &NativeProgram,
        input: &FrameInput<'_>,
        world: &dyn WorldQuery,
        debug: bool,
    ) -> Result<(), NativeMismatch> {
        if self.native_checked != Some(native.fingerprint) {
            let program = crate::native::fingerprint(&self.program);
            if program != native.fingerprint {
                return Err(NativeMismatch {
                    graph: self.program.name.clone(),
                    program,
                    native: native.fingerprint,
                });
            }
            self.native_checked = Some(program);
        }
        let dt = self.begin_frame(input, debug);
        self.run_event(Body::Native(native.forward), world, dt);
        Ok(())
    }

    /// Applies a frame's input (placement, start pose, debug switch) and returns its dt.
    fn begin_frame(&mut self, input: &FrameInput<'_>, debug: bool) -> f32 {
        if input.component_to_world.is_finite() {
            self.to_world = input.component_to_world;
        }
        match input.pose {
            InputPose::Rest => self.pose.reset_to_rest(),
            InputPose::Previous => {}
            InputPose::Locals(locals) => self.pose.set_locals(locals),
        }
        if self.debug.is_enabled() != debug {
            self.debug.set_enabled(debug);
        }
        self.debug.clear();
        if input.dt.is_finite() && input.dt > 0.0 {
            input.dt
        } else {
            0.0
        }
    }

    /// Runs one frame of the `forward` event on every instance of `crowd`, the same as
    /// calling [`Instance::run_forward`] on each with `input(i)` for instance `i`, with
    /// bit-identical results — but faster: instances that run the same program (the same
    /// `Arc`) go through the interpreter up to 16 at a time, each instruction dispatched
    /// once for all of them (instances that branch apart continue separately and meet again
    /// where their paths do), and while all of them are at one instruction its plain
    /// scalar math runs for all of them as one vectorised loop. The batches are picked from
    /// the whole of `crowd`: instances of one program whose last frames took the same path
    /// through it ([`Instance::path_key`]) go together in whole batches of 16, as they
    /// likely take one path again (characters at different points of their walk cycles
    /// branch apart at every foot; batched by path, they rarely do); after all of those,
    /// the others go path after path, each next path the one whose jumps are most like the
    /// last one's ([`Instance::jump_sites`]), so that the batches holding several paths
    /// split as little as they can. Which instances share a batch never changes any result;
    /// `input` is called once per instance, in that order (not the crowd's). Instances with profiling on are batched with each other only: each
    /// dispatch's time is shared among the members at it, each counted as having run the
    /// instruction (see `Instance::profile`, with the `profile` feature). The one latitude in
    /// "bit-identical" is a NaN result's sign and payload bits, which Rust leaves open (a
    /// NaN stays a NaN). A program with fewer than two instructions per scalar slot runs
    /// its batches on each instance's own slots, without the vectorised loops, whose
    /// copies it would not win back.
    ///
    /// Without `debug`, a batch on lanes leaves alone the slots of values that live only
    /// within a run (node outputs that share a slot with others, see
    /// [`Program::pin_slots`]): it copies back graph variables and state, and those slots
    /// keep what the instance's last run alone or with `debug` left there. With `debug` it
    /// copies back every slot an instruction writes, so every pin value reads as after
    /// [`Instance::run_forward`].
    ///
    /// For threads, split the crowd into a few large chunks (rayon's `par_chunks_mut` with
    /// a chunk of the crowd's size divided by the thread count, rounded up, at least 1) and call this on each:
    /// the larger the chunk, the more instances there are to pick each batch's path-sharing
    /// members from. Allocates nothing after warm-up: each thread keeps one scratch copy of
    /// 16 instances' scalar slots and one of their IK chains, made by its first batch, and
    /// the lists the crowd is ordered in, grown to the largest crowd it has run (a batch
    /// run from inside another on the same thread, by a world query that runs a rig of its
    /// own, makes its own). A worker thread that has run no batch yet makes them on its
    /// first: [`Instance::reserve_batch_scratch`] makes them ahead.
    ///
    /// # Panics
    /// If `crowd` has more than `u32::MAX` instances (hundreds of terabytes of them): the
    /// order numbers them in 32 bits. Split such a crowd.
    pub fn run_forward_batch<'i>(
        crowd: &mut [Instance],
        mut input: impl FnMut(usize) -> FrameInput<'i>,
        world: &dyn WorldQuery,
        debug: bool,
    ) {
        assert!(
            u32::try_from(crowd.len()).is_ok(),
            "a batched crowd has at most u32::MAX instances: split it"
        );
        // The thread's scratch lists, grown once.
        let mut scratch = ORDER.with(std::cell::Cell::take);
        batch_order(crowd, &mut scratch);
        let order = &mut scratch.order;
        let mut start = 0;
        while start < order.len() {
            let first = &crowd[order[start]];
            let mut end = start + 1;
            while end < order.len()
                && end - start < exec::BATCH
                && Arc::ptr_eq(&crowd[order[end]].program, &first.program)
                && crowd[order[end]].is_profiling() == first.is_profiling()
            {
                end += 1;
            }
            // The batch's instances in crowd order: picked from one pass over the crowd.
            let batch = &mut order[start..end];
            batch.sort_unstable();
            if let [single] = *batch {
                crowd[single].run_forward(&input(single), world, debug);
            } else {
                let mut program = None;
                let mut members = smallvec::SmallVec::<[Ctx<'_>; exec::BATCH]>::new();
                let mut instances = crowd.iter_mut();
                let mut next = 0;
                let mut unwritten_initial = true;
                for &i in batch.iter() {
                    let instance = instances
                        .nth(i - next)
                        .expect("a batch's indices are the crowd's, ascending");
                    next = i + 1;
                    unwritten_initial &= instance.unwritten_changed == 0;
                    let dt = instance.begin_frame(&input(i), debug);
                    let (p, cx) = instance.event_context(world, dt);
                    program = Some(p);
                    members.push(cx);
                }
                if let Some(p) = program {
                    // The dispatch count it returns is for the executor's tests.
                    exec::run_batch(
                        &p.code,
                        &p.operands,
                        p.forward,
                        crate::lanes::Copies {
                            lens: &p.scalar_lens,
                            // With debug every written slot goes back: pin values too.
                            kept: if debug { &p.written_lens } else { &p.kept_lens },
                            written: &p.written_lens,
                            program: if unwritten_initial { p.id } else { 0 },
                            initial: &p.initial,
                        },
                        &mut members,
                    );
                }
                let paths: smallvec::SmallVec<[(u64, u64); exec::BATCH]> =
                    members.iter().map(|cx| (cx.path, cx.taken)).collect();
                drop(members);
                for (&i, (path, taken)) in batch.iter().zip(paths) {
                    crowd[i].path = path;
                    crowd[i].taken = taken;
                }
            }
            start = end;
        }
        ORDER.with(|cell| cell.set(scratch));
    }

    /// Grows the calling thread's scratch for [`Instance::run_forward_batch`] to what it
    /// needs for crowds of up to `crowd` instances of `program`, so that the thread's next
    /// batches allocate nothing even when it has run none: the scalar lanes (when
    /// `program`'s batches run on them), the IKs' chain lanes (when it has a `TwoBoneIK`)
    /// and the lists the crowd is ordered in. A thread grows these by itself on its first
    /// batches; a crowd split over a thread pool should call this on every worker once
    /// before the frames that must not allocate (with rayon,
    /// `pool.broadcast(|_| Instance::reserve_batch_scratch(&program, chunk))`), since the
    /// scheduler may hand a worker its first share of the crowd at any frame. Cheap when
    /// the scratch is large enough already; does nothing to the lanes of a batch running
    /// on this thread (called from inside a world query).
    pub fn reserve_batch_scratch(program: &Program, crowd: usize) {
        exec::reserve_batch_scratch(&program.code, &program.scalar_lens, &program.initial);
        let mut scratch = ORDER.with(std::cell::Cell::take);
        scratch.reserve(crowd);
        ORDER.with(|cell| cell.set(scratch));
    }

    /// Runs an event's code on this instance.
    fn run_event(&mut self, body: Body, world: &dyn WorldQuery, dt: f32) {
        let (program, mut cx) = self.event_context(world, dt);
        match body {
            Body::Program(entry) => {
                exec::run(program, entry, &mut cx);
                let (path, taken) = (cx.path, cx.taken);
                self.path = path;
                self.taken = taken;
            }
            Body::Native(forward) => {
                #[cfg(feature = "profile")]
                {
                    cx.profile = None;
                }
                forward(&mut crate::native::Frame { cx });
            }
        }
    }

    /// The program, and what a run of its event with time step `dt` works on: this
    /// instance's state, the program's texts and the next run number.
    fn event_context<'a>(
        &'a mut self,
        world: &'a dyn WorldQuery,
        dt: f32,
    ) -> (&'a Program, Ctx<'a>) {
        // The executor indexes scalar slots unchecked (see `exec`): make sure they still
        // cover the program's.
        self.slots.cover(&self.program.scalar_lens);
        let (to_world_matrix, from_world_matrix) = if self.program.traces {
            (
                self.to_world.to_affine(),
                self.to_world.inverse().to_affine(),
            )
        } else {
            (Affine3A::IDENTITY, Affine3A::IDENTITY)
        };
        let cx = Ctx {
            slots: &mut self.slots,
            texts: &self.program.texts,
            pose: &mut self.pose,
            debug: &mut self.debug,
            world,
            dt,
            to_world: self.to_world,
            to_world_matrix,
            from_world_matrix,
            run: next_run(&mut self.runs),
            path: 0,
            taken: 0,
            #[cfg(feature = "profile")]
            profile: self.profiling.then_some(&mut self.profile[..]),
        };
        (&self.program, cx)
    }

    /// The key of the path the last interpreted run took through the program (a run of
    /// native code leaves it as it was): the jumps it took, in order, folded into 64 bits. Runs through the same instructions have the same key,
    /// alone or batched; different paths almost always have different ones. Before the
    /// first frame, the construction run's key. [`Instance::run_forward_batch`] batches
    /// instances with equal keys together; a host that splits a crowd between threads
    /// itself can sort by it first.
    #[must_use]
    pub fn path_key(&self) -> u64 {
        self.path
    }

    /// The instructions the last interpreted run jumped from, as a set: bit `k` is set
    /// when it jumped from an instruction whose index is `k` modulo 64 (a run of native
    /// code leaves it as it was). Unlike [`Instance::path_key`] it keeps no order or count,
    /// so runs that share most of their jumps have sets that differ in few bits; the same
    /// alone or batched. [`Instance::run_forward_batch`] orders the instances it cannot put
    /// in whole batches of one path by it.
    #[must_use]
    pub fn jump_sites(&self) -> u64 {
        self.taken
    }

    /// The output pose. Call [`Pose::globals`] on it for rig-space transforms.
    #[must_use]
    pub fn pose(&self) -> &Pose {
        &self.pose
    }

    /// The output pose, mutable (globals are computed lazily).
    pub fn pose_mut(&mut self) -> &mut Pose {
        &mut self.pose
    }

    /// Debug primitives drawn by the last frame (empty unless it ran with `debug`).
    #[must_use]
    pub fn debug_draw(&self) -> &DebugDraw {
        &self.debug
    }

    /// Bytes of memory the instance holds: itself, its slots, its pose and its debug-draw
    /// buffer (the program and the skeleton are shared, and not counted). What one more
    /// character of a crowd costs, and what its frame reads and writes.
    #[must_use]
    pub fn memory_bytes(&self) -> usize {
        #[cfg(feature = "profile")]
        let profile = self.profile.capacity() * std::mem::size_of::<crate::profile::InstrProfile>();
        #[cfg(not(feature = "profile"))]
        let profile = 0;
        std::mem::size_of::<Self>()
            + self.slots.heap_bytes()
            + self.pose.heap_bytes()
            + self.debug.heap_bytes()
            + profile
    }

    /// The instance's slot memory (for inspection).
    #[must_use]
    pub fn slots(&self) -> &Slots {
        &self.slots
    }

    /// A variable's current value. Bones read back by name. Allocates for arrays and
    /// bones: for tools, not for the frame loop.
    #[must_use]
    pub fn variable(&self, id: VariableId) -> Value {
        let info = self.program.variable(id);
        let skeleton = self.pose.skeleton();
        let bone_name = |b: i32| {
            (b >= 0)
                .then(|| skeleton.names().get(b as usize).cloned())
                .flatten()
        };
        match info.ty {
            ValueType::Bone => Value::Bone(bone_name(self.slots.bones[info.slot as usize])),
            ValueType::Array(strider_nodes::Elem::Bone) => Value::Array(
                strider_nodes::Elem::Bone,
                self.slots.bone_arrays[info.slot as usize]
                    .iter()
                    .map(|&b| Value::Bone(bone_name(b)))
                    .collect(),
            ),
            ty => self.slots.read(ty, info.slot),
        }
    }

    /// Sets a variable (a tunable from the host or the inspector, or any state). An `Int`
    /// value is accepted for a `Float` variable. See [`Instance::set_float`] for what a
    /// value other than the default costs a batch.
    ///
    /// # Errors
    /// When the value's type is not the variable's, or a bone name is unknown.
    pub fn set_variable(&mut self, id: VariableId, value: &Value) -> Result<(), VariableError> {
        let info = self.program.variable(id);
        let (ty, slot) = (info.ty, info.slot);
        let was = self.unwritten_differs(ty, slot);
        let value = match (info.ty, value) {
            (ValueType::Float, Value::Int(i)) => Value::Float(*i as f32),
            _ => value.clone(),
        };
        if value.ty() != info.ty {
            return Err(VariableError::TypeMismatch {
                name: info.name.clone(),
                expected: info.ty,
                found: value.ty(),
            });
        }
        let skeleton = self.pose.skeleton();
        let find =
            |name: &Option<String>| -> Result<i32, VariableError> {
                match name {
                    None => Ok(-1),
                    Some(n) => skeleton.find(n).map(|b| b.0 as i32).ok_or_else(|| {
                        VariableError::UnknownBone {
                            name: info.name.clone(),
                            bone: n.clone(),
                        }
                    }),
                }
            };
        match &value {
            Value::Bone(name) => self.slots.bones[info.slot as usize] = find(name)?,
            Value::Array(strider_nodes::Elem::Bone, items) => {
                let mut bones = Vec::with_capacity(items.len());
                for item in items {
                    if let Value::Bone(name) = item {
                        bones.push(find(name)?);
                    }
                }
                self.slots.bone_arrays[info.slot as usize] = bones;
            }
            v => self.slots.write(info.slot, v),
        }
        self.note_set(ty, slot, was);
        Ok(())
    }

    /// Whether slot `slot` of type `ty` is one that no instruction writes and holds other
    /// bits than the program's initial value there.
    fn unwritten_differs(&self, ty: ValueType, slot: u32) -> bool {
        let Some(t) = crate::slots::scalar(ty) else {
            return false;
        };
        let (s, now, initial) = (slot as usize, &self.slots, &self.program.initial);
        if s < self.program.written_lens.0[t] {
            return false;
        }
        match ty {
            ValueType::Bool => !now.bools[s].same_bits(&initial.bools[s]),
            ValueType::Int => !now.ints[s].same_bits(&initial.ints[s]),
            ValueType::Float => !now.floats[s].same_bits(&initial.floats[s]),
            ValueType::Vec3 => !now.vec3s[s].same_bits(&initial.vec3s[s]),
            ValueType::Quat => !now.quats[s].same_bits(&initial.quats[s]),
            ValueType::Transform => !now.transforms[s].same_bits(&initial.transforms[s]),
            _ => false,
        }
    }

    /// Counts the host's write of slot `slot` of type `ty` (which held other bits than the
    /// program's initial value before it when `was`) in `unwritten_changed`.
    fn note_set(&mut self, ty: ValueType, slot: u32, was: bool) {
        let now = self.unwritten_differs(ty, slot);
        self.unwritten_changed = self.unwritten_changed + u32::from(now) - u32::from(was);
    }

    /// Sets a `Float` variable without allocating: the per-frame path for tunables.
    /// Ignored if the variable is not a float. While a variable that no instruction writes
    /// holds other bits than its default here, this instance's batches
    /// ([`Instance::run_forward_batch`]) copy such slots member by member instead of
    /// keeping the program's in the thread's lanes (the same results, a little slower).
    pub fn set_float(&mut self, id: VariableId, value: f32) {
        let info = self.program.variable(id);
        if info.ty == ValueType::Float {
            let slot = info.slot;
            let was = self.unwritten_differs(ValueType::Float, slot);
            self.slots.floats[slot as usize] = value;
            self.note_set(ValueType::Float, slot, was);
        }
    }
}

/// An instance's place in [`batch_order`]'s sort, read off the instance once per frame
/// and packed into one integer, so that the sort compares and moves two machine words
/// rather than five fields. From the top: its program's address, with bit 0 set when it
/// profiles (64 bits: the address of a `Program` is even); its last run's path key
/// ([`Instance::path_key`]) folded to 32 bits; its index in the crowd (32 bits). Two paths
/// that fold alike are ordered as one, which can cost their batches a split, never a
/// result: a batch is formed of one program's instances whatever the order.
type OrderKey = u128;

const _: () = assert!(
    std::mem::align_of::<Program>() >= 2,
    "an OrderKey keeps the profiling flag in bit 0 of the program's address"
);

/// `instance`'s [`OrderKey`] at `index` in its crowd (of at most `u32::MAX` instances).
fn order_key(instance: &Instance, index: usize) -> OrderKey {
    let program =
        Arc::as_ptr(&instance.program) as usize as u64 | u64::from(instance.is_profiling());
    let path = (instance.path ^ (instance.path >> 32)) as u32;
    (u128::from(program) << 64) | (u128::from(path) << 32) | index as u128
}

/// The crowd index an [`OrderKey`] holds.
fn key_index(key: OrderKey) -> usize {
    key as u32 as usize
}

/// The program, profiling flag and folded path of an [`OrderKey`]: equal for instances
/// batched as of one path.
fn key_path(key: OrderKey) -> u128 {
    key >> 32
}

/// The program and profiling flag of an [`OrderKey`]: equal for instances that may share
/// a batch.
fn key_program(key: OrderKey) -> u128 {
    key >> 64
}

/// The order `Instance::run_forward_batch` takes a crowd's instances in, and the scratch
/// lists it is worked out in: kept by each thread and grown to its largest crowd once.
#[derive(Default)]
struct BatchOrder {
    /// Indices into the crowd, consecutive instances of one program forming its batches.
    order: Vec<usize>,
    /// Every instance's sort key.
    keys: Vec<OrderKey>,
    /// The keys of the instances outside whole batches of one path.
    rest: Vec<OrderKey>,
    /// One program's runs of one path in `rest`, as ranges of it.
    paths: Vec<(usize, usize)>,
}

impl BatchOrder {
    /// Makes room in every list for a crowd of `crowd` instances, whatever its paths: a
    /// crowd that falls out of step later grows none of them.
    fn reserve(&mut self, crowd: usize) {
        let Self {
            order,
            keys,
            rest,
            paths,
        } = self;
        order.reserve(crowd.saturating_sub(order.len()));
        keys.reserve(crowd.saturating_sub(keys.len()));
        rest.reserve(crowd.saturating_sub(rest.len()));
        paths.reserve(crowd.saturating_sub(paths.len()));
    }
}

/// At most this many paths outside whole batches, per program, are ordered by likeness
/// ([`order_by_likeness`], whose search grows with their square); more go in crowd order.
const LIKENESS_PATHS: usize = 128;

/// Works out the order `Instance::run_forward_batch` takes `crowd`'s instances in, as
/// indices into it (`scratch.order`), consecutive instances of one program forming its
/// batches. First, program by program (and profiling choice by choice), whole batches of
/// [`exec::BATCH`] instances whose last runs took one path ([`Instance::path_key`]): they
/// likely take that path again, and a batch whose members take one path dispatches each
/// instruction once for all of them. Then, program by program, the others (a path's last
/// few, and the paths too rare to fill a batch), path after path, each next path the most
/// like the one before ([`order_by_likeness`]), so that a batch that holds several paths
/// holds paths that share most of their jumps. Ties in crowd order everywhere.
fn batch_order(crowd: &[Instance], scratch: &mut BatchOrder) {
    scratch.reserve(crowd.len());
    let BatchOrder {
        order,
        keys,
        rest,
        paths,
    } = scratch;
    keys.clear();
    keys.extend(
        crowd
            .iter()
            .enumerate()
            .map(|(i, instance)| order_key(instance, i)),
    );
    keys.sort_unstable();
    // Each run of one path gives its whole batches to the order, in crowd order; the
    // remainders go to `rest`.
    order.clear();
    rest.clear();
    for run in keys.chunk_by(|&a, &b| key_path(a) == key_path(b)) {
        let (whole, part) = run.split_at(run.len() / exec::BATCH * exec::BATCH);
        order.extend(whole.iter().map(|&k| key_index(k)));
        rest.extend_from_slice(part);
    }
    // `rest` is sorted as `keys`: program by program, path by path.
    for program in rest.chunk_by_mut(|&a, &b| key_program(a) == key_program(b)) {
        order_by_likeness(program, crowd, paths, order);
    }
}

/// Appends one program's instances outside whole batches (`rest`, sorted by path key,
/// then crowd index) to `order`, path after path: first the path of the crowd's first
/// instance among them, then each time the path left whose jump sites
/// ([`Instance::jump_sites`]) differ in the fewest bits from the last one's (ties: the one
/// whose first instance comes first in the crowd). Two characters a little apart in their
/// cycles (one foot about to land, the other just landed) differ in a few jumps; a batch
/// of both splits only there. With more than [`LIKENESS_PATHS`] paths, the instances go in
/// crowd order instead. `paths` is scratch.
fn order_by_likeness(
    rest: &mut [OrderKey],
    crowd: &[Instance],
    paths: &mut Vec<(usize, usize)>,
    order: &mut Vec<usize>,
) {
    paths.clear();
    let mut start = 0;
    for run in rest.chunk_by(|&a, &b| key_path(a) == key_path(b)) {
        paths.push((start, start + run.len()));
        start += run.len();
    }
    if paths.len() > LIKENESS_PATHS {
        rest.sort_unstable_by_key(|&k| key_index(k));
        order.extend(rest.iter().map(|&k| key_index(k)));
        return;
    }
    // A path's first instance in the crowd, and its jump sites.
    let first = |p: usize| key_index(rest[paths[p].0]);
    let sites = |p: usize| crowd[first(p)].taken;
    // The paths not yet ordered, one bit each (`LIKENESS_PATHS` fit).
    let mut left = u128::MAX >> (128 - paths.len());
    let mut at = (0..paths.len()).min_by_key(|&p| first(p)).unwrap_or(0);
    loop {
        left &= !(1 << at);
        let (start, end) = paths[at];
        order.extend(rest[start..end].iter().map(|&k| key_index(k)));
        if left == 0 {
            return;
        }
        let mut best = (u32::MAX, usize::MAX, 0);
        let mut bits = left;
        while bits != 0 {
            let p = bits.trailing_zeros() as usize;
            bits &= bits - 1;
            best = best.min(((sites(p) ^ sites(at)).count_ones(), first(p), p));
        }
        at = best.2;
    }
}

thread_local! {
    /// Each thread's order of a crowd for `Instance::run_forward_batch`, with its scratch
    /// lists.
    static ORDER: std::cell::Cell<BatchOrder> = const {
        std::cell::Cell::new(BatchOrder {
            order: Vec::new(),
            keys: Vec::new(),
            rest: Vec::new(),
            paths: Vec::new(),
        })
    };
}

/// The code an event runs.
enum Body {
    /// The interpreter, from this instruction.
    Program(u32),
    /// Code generated ahead of time.
    Native(fn(&mut crate::native::Frame<'_>)),
}

/// Generated code was made from another program than the instance's
/// ([`Instance::run_forward_native`]).
#[derive(Clone, Debug, PartialEq, Eq, thiserror::Error)]
#[error(
    "the native code was generated from another program than `{graph}` (fingerprint {native:#018x}, the program's is {program:#018x})\n  hint: regenerate it from the current graph"
)]
pub struct NativeMismatch {
    /// The instance's graph.
    pub graph: String,
    /// The instance's program's fingerprint.
    pub program: u64,
    /// The fingerprint the native code was generated from.
    pub native: u64,
}

/// The next run number: counts up, wrapping past `i32::MAX` to 1 (0 means "never ran").
fn next_run(runs: &mut i32) -> i32 {
    *runs = if *runs == i32::MAX { 1 } else { *runs + 1 };
    *runs
}

fn copy_slot(from: &Slots, to: &mut Slots, ty: ValueType, slot: u32) {
    let s = slot as usize;
    match ty {
        ValueType::Bool => to.bools[s] = from.bools[s],
        ValueType::Int => to.ints[s] = from.ints[s],
        ValueType::Float => to.floats[s] = from.floats[s],
        ValueType::Vec3 => to.vec3s[s] = from.vec3s[s],
        ValueType::Quat => to.quats[s] = from.quats[s],
        ValueType::Transform => to.transforms[s] = from.transforms[s],
        // Bones index the old skeleton; arrays of any kind are rebuilt by construction.
        _ => {}
    }
}

impl fmt::Display for MissingBone {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: unknown bone `{}`", self.location, self.name)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ProgramBuilder;
    use crate::program::VariableInfo;
    use crate::tests::one_bone;
    use strider_nodes::Op;

    /// A crowd's batch order: for each program (in the order of their addresses), whole
    /// batches of instances whose last runs took one path, in key order; then each
    /// program's other instances (here all of one set of jump sites, so path by path in
    /// the crowd order of their first instances, which is crowd order). Profiling
    /// instances count as a program of their own.
    #[test]
    fn a_crowd_is_ordered_in_whole_batches_of_one_path_then_the_rest() {
        let program = |name: &str| {
            let mut pb = ProgramBuilder::new(name);
            pb.set_forward_entry(pb.here());
            pb.emit(Op::End, &[]);
            Arc::new(pb.finish())
        };
        let (a, b) = (program("a"), program("b"));
        // Program a: 17 instances of path 5 and 16 of path 2, interleaved, then 7 of path
        // 9 (too few for a batch); program b: 3 of path 2, between them.
        let mut of: Vec<(&Arc<Program>, u64)> = Vec::new();
        for k in 0..33 {
            of.push((&a, if k % 2 == 0 { 5 } else { 2 }));
            if k % 11 == 0 {
                of.push((&b, 2));
            }
        }
        of.extend([(&a, 9); 7]);
        let crowd: Vec<Instance> = of
            .iter()
            .map(|&(p, path)| {
                let mut instance = Instance::new(Arc::clone(p), one_bone()).expect("instance");
                instance.path = path;
                instance
            })
            .collect();
        let of_path = |p: &Arc<Program>, path: u64| -> Vec<usize> {
            (0..of.len())
                .filter(|&i| Arc::ptr_eq(of[i].0, p) && of[i].1 == path)
                .collect()
        };
        let of_program = |p: &Arc<Program>| -> Vec<usize> {
            (0..of.len()).filter(|&i| Arc::ptr_eq(of[i].0, p)).collect()
        };
        let (twos, fives) = (of_path(&a, 2), of_path(&a, 5));
        assert_eq!((twos.len(), fives.len()), (16, 17));
        // a's whole batches: path 2's 16, path 5's first 16; the rest in crowd order.
        let whole = [twos.clone(), fives[..16].to_vec()].concat();
        let rest_a: Vec<usize> = of_program(&a)
            .into_iter()
            .filter(|i| !whole.contains(i))
            .collect();
        let rest_b = of_program(&b);
        let a_first = Arc::as_ptr(&a) < Arc::as_ptr(&b);
        let by_program = |of_a: Vec<usize>, of_b: Vec<usize>| {
            if a_first {
                [of_a, of_b].concat()
            } else {
                [of_b, of_a].concat()
            }
        };
        let expected = [whole, by_program(rest_a, rest_b.clone())].concat();
        let mut scratch = BatchOrder {
            order: vec![99],
            keys: vec![97],
            rest: vec![98],
            paths: vec![(96, 95)],
        };
        batch_order(&crowd, &mut scratch);
        assert_eq!(scratch.order, expected);
        #[cfg(feature = "profile")]
        {
            // One of path 2's instances profiles: it is of a program of its own (after a's
            // plain one), and path 2 no longer fills a batch.
            let mut crowd = crowd;
            let profiling = twos[3];
            crowd[profiling].set_profiling(true);
            batch_order(&crowd, &mut scratch);
            let plain_rest: Vec<usize> = of_program(&a)
                .into_iter()
                .filter(|i| !fives[..16].contains(i) && *i != profiling)
                .collect();
            let rest_a = [plain_rest, vec![profiling]].concat();
            let expected = [fives[..16].to_vec(), by_program(rest_a, rest_b)].concat();
            assert_eq!(scratch.order, expected);
        }
    }

    /// A program named `name` whose forward event only ends.
    fn ending(name: &str) -> Arc<Program> {
        let mut pb = ProgramBuilder::new(name);
        pb.set_forward_entry(pb.here());
        pb.emit(Op::End, &[]);
        Arc::new(pb.finish())
    }

    /// An order key holds the crowd index in its low 32 bits, and compares first by
    /// program and profiling flag, then by the path key folded to 32 bits (its halves
    /// exclusive-or'd), then by index.
    #[test]
    fn an_order_key_packs_program_profiling_folded_path_and_index() {
        let program = ending("keys");
        let with_path = |path: u64| {
            let mut instance = Instance::new(Arc::clone(&program), one_bone()).expect("instance");
            instance.path = path;
            instance
        };
        let (a, b) = (
            with_path(0x0000_0001_0000_0003),
            with_path(0x0000_0002_0000_0003),
        );
        let (ka, kb) = (order_key(&a, 7), order_key(&b, 3));
        assert_eq!((key_index(ka), key_index(kb)), (7, 3));
        assert_eq!(key_program(ka), key_program(kb));
        assert_eq!(key_program(ka), Arc::as_ptr(&program) as u128);
        // 1 ^ 3 = 2 and 2 ^ 3 = 1: b's folded path sorts first, whatever the indices.
        assert_eq!(key_path(ka) & 0xFFFF_FFFF, 2);
        assert_eq!(key_path(kb) & 0xFFFF_FFFF, 1);
        assert!(kb < ka);
        // Keys that fold alike are one path; the index then orders them.
        let c = with_path(0x0000_0003_0000_0001);
        assert_eq!(key_path(order_key(&c, 9)), key_path(ka));
        assert!(ka < order_key(&c, 9));
    }

    /// The instances outside whole batches go path after path, each next path the one
    /// whose jump sites differ least from the last one's, from the path of the crowd's
    /// first of them; ties in crowd order. With more paths than `LIKENESS_PATHS`, crowd
    /// order.
    #[test]
    fn paths_too_rare_for_a_batch_follow_each_other_by_likeness() {
        let program = ending("likeness");
        // (path, jump sites) by crowd index: path 4 first in the crowd, then paths 2, 1, 3,
        // 5 interleaved. From path 4 (sites 0b0001), path 3 (0b0011) and path 5 (0b1001)
        // both differ in one bit: path 3 has the earlier first instance. From 3, path 1
        // (0b0111, one bit) before paths 2 and 5 (two bits each); from 1, path 2 (0b1111,
        // one bit) before path 5 (three bits).
        let of: [(u64, u64); 9] = [
            (4, 0b0001),
            (2, 0b1111),
            (1, 0b0111),
            (3, 0b0011),
            (5, 0b1001),
            (2, 0b1111),
            (3, 0b0011),
            (1, 0b0111),
            (4, 0b0001),
        ];
        let crowd_of = |of: &[(u64, u64)]| -> Vec<Instance> {
            of.iter()
                .map(|&(path, sites)| {
                    let mut instance =
                        Instance::new(Arc::clone(&program), one_bone()).expect("instance");
                    instance.path = path;
                    instance.taken = sites;
                    instance
                })
                .collect()
        };
        let mut scratch = BatchOrder::default();
        batch_order(&crowd_of(&of), &mut scratch);
        // Paths 4, 3, 1, 2, 5; each path's instances in crowd order.
        assert_eq!(scratch.order, [0, 8, 3, 6, 2, 7, 1, 5, 4]);
        // One instance per path, more paths than are ordered by likeness: crowd order.
        let many: Vec<(u64, u64)> = (0..LIKENESS_PATHS as u64 + 1)
            .map(|k| (1000 - k, k % 7))
            .collect();
        batch_order(&crowd_of(&many), &mut scratch);
        assert_eq!(scratch.order, (0..many.len()).collect::<Vec<_>>());
    }

    /// The count of unwritten slots that differ from the program's follows the host's
    /// writes bit for bit: up when a tunable is set to another value, not again when it
    /// is set to a third, down when it is set back; `-0.0` differs from `0.0`, a NaN equals
    /// the same NaN; a variable an instruction writes is not counted; a rebind counts the
    /// tunables it keeps.
    #[test]
    fn the_host_s_changes_to_unwritten_slots_are_counted_both_ways() {
        let mut pb = ProgramBuilder::new("tunables");
        let variable = |pb: &mut ProgramBuilder, name: &str, value: f32| {
            let slot = pb.constant(&Value::Float(value), "");
            let id = pb.variable(VariableInfo {
                name: name.to_string(),
                ty: ValueType::Float,
                slot,
                default: Value::Float(value),
                tunable: Some((None, None)),
                location: String::new(),
            });
            (id, slot)
        };
        // The written variable first: the slots past the last written one are those a
        // batch can take from the program.
        let (written, written_slot) = variable(&mut pb, "Written", 1.0);
        let (zero, _) = variable(&mut pb, "Zero", 0.0);
        let (nan, _) = variable(&mut pb, "Nan", f32::NAN);
        pb.set_forward_entry(pb.here());
        pb.emit(Op::AddF, &[written_slot, written_slot, written_slot]);
        pb.emit(Op::End, &[]);
        let program = Arc::new(pb.finish());
        let mut instance = Instance::new(Arc::clone(&program), one_bone()).expect("instance");
        let count = |i: &Instance| i.unwritten_changed;
        assert_eq!(count(&instance), 0);
        instance.set_float(zero, 2.0);
        assert_eq!(count(&instance), 1);
        instance.set_float(zero, 3.0);
        assert_eq!(count(&instance), 1, "still one slot apart");
        instance
            .set_variable(zero, &Value::Float(0.0))
            .expect("a float");
        assert_eq!(count(&instance), 0, "set back");
        instance.set_float(zero, -0.0);
        assert_eq!(count(&instance), 1, "-0.0 is not 0.0's bits");
        instance.set_float(nan, f32::NAN);
        assert_eq!(count(&instance), 1, "the same NaN");
        instance.set_float(nan, 1.0);
        assert_eq!(count(&instance), 2);
        instance.set_float(written, 5.0);
        assert_eq!(count(&instance), 2, "an instruction writes that one");
        instance.rebind(one_bone(), &EmptyWorld).expect("rebinds");
        assert_eq!(count(&instance), 2, "the tunables are kept");
        instance.set_float(nan, f32::NAN);
        instance.set_float(zero, 0.0);
        assert_eq!(count(&instance), 0);
    }
}
