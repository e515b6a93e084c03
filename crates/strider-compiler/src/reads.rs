//! What a pure node's value depends on, beyond its own inputs: the graph variables, the
//! function locals and the pose it reads, directly or through the pure nodes and pure
//! function calls it pulls. Code generation keeps a pure node's value for later steps until
//! a step writes one of these (see `codegen.rs`).
//!
//! A function's inputs are constant while its body runs; constants, the frame's dt, the
//! world transform and the world (traces) are constant for a whole run, and stateful nodes
//! advance once per run, so none of them ends a value's life. Loop variables do, but values
//! are never kept across loop iterations.

use crate::check::{Body, CStep, Checked, NodeKind, Src, VarRef};
use fixedbitset::FixedBitSet;
use strider_nodes::Op;

/// The mutable state a value was computed from: a row of its body's [`BodyReads`] and
/// flags.
#[derive(Clone, Copy)]
pub(crate) struct Reads<'t> {
    /// One bit per graph variable, local and exec node of the body it reads (the layout is
    /// `body`'s).
    row: &'t [u64],
    /// [`POSE`], [`LOOP_VARS`], [`STATEFUL`].
    flags: u8,
    /// The body's layout of a row.
    body: &'t BodyReads,
}

/// A [`Reads`] flag: the value reads the pose (a bone transform).
const POSE: u8 = 1;
/// A [`Reads`] flag: the value reads a loop's element, index or count.
const LOOP_VARS: u8 = 2;
/// A [`Reads`] flag: the value is or pulls a stateful node (whose state advances when first
/// evaluated in a run, so it must not be evaluated where the graph would not evaluate it).
const STATEFUL: u8 = 4;
/// A flag of [`BodyReads::flags`]: the node's row is filled in.
const KNOWN: u8 = 8;

impl Reads<'_> {
    /// Whether it reads a loop's element, index or count.
    pub(crate) fn loop_vars(&self) -> bool {
        self.flags & LOOP_VARS != 0
    }

    /// Whether it is or pulls a stateful node.
    pub(crate) fn stateful(&self) -> bool {
        self.flags & STATEFUL != 0
    }

    fn bit(&self, b: usize) -> bool {
        self.row[b / 64] & (1 << (b % 64)) != 0
    }
}

/// Whether a built-in op reads the pose's current bone transforms. (`GetParent` and
/// `FindBones` read the skeleton, which never changes.)
pub(crate) fn reads_pose(op: Op) -> bool {
    matches!(op, Op::GetTransform)
}

/// Whether a mutating built-in op may change the pose. Draws and array edits do not;
/// anything else mutating is assumed to.
pub(crate) fn writes_pose(op: Op) -> bool {
    !(op.is_draw() || matches!(op, Op::ArraySetAt(_) | Op::ArrayAdd(_) | Op::ArrayReset(_)))
}

/// What running a list of steps may change in its frame: the other side of [`Reads`].
#[derive(Clone, Debug, Default)]
pub(crate) struct Writes {
    /// Variables and locals set, or edited in place by a mutating node.
    pub vars: Vec<VarRef>,
    /// Exec nodes run (their outputs change).
    pub execs: Vec<usize>,
    /// The pose may move.
    pub pose: bool,
    /// Any graph variable may change (an impure function call).
    pub any_global: bool,
    /// A mutating node edits a pure node's output in place: nothing is safe to keep.
    pub everything: bool,
}

impl Writes {
    /// Whether a value that reads `r` may be changed by these writes.
    pub(crate) fn touch(&self, r: &Reads) -> bool {
        let layout = r.body;
        self.everything
            || (self.pose && r.flags & POSE != 0)
            || (self.any_global && r.row[..layout.global_words].iter().any(|&w| w != 0))
            || self
                .execs
                .iter()
                .any(|&e| layout.exec_bit(e).is_some_and(|b| r.bit(b)))
            || self.vars.iter().any(|&v| r.bit(layout.var_bit(v)))
    }

    /// Adds what `steps` of `body` may change (nested lists included; function bodies are
    /// summarised by their call: an impure call may change any variable and the pose).
    pub(crate) fn collect(&mut self, body: &Body, steps: &[CStep]) {
        each_step(steps, |s| match s {
            CStep::Set { target, .. } => self.vars.push(*target),
            CStep::Exec(n) => {
                self.execs.push(*n);
                let node = &body.nodes[*n];
                match node.kind {
                    NodeKind::Builtin(op) => {
                        // Only arrays are edited in place (a node's `target` pins, which
                        // the checker requires to be variables); a scalar input is only
                        // read.
                        for a in node.inputs.iter().filter(|a| a.ty.is_array()) {
                            match a.src {
                                Src::Global(g) => self.vars.push(VarRef::Global(g)),
                                Src::Local(l) => self.vars.push(VarRef::Local(l)),
                                Src::Node { .. } => self.everything = true,
                                _ => {}
                            }
                        }
                        self.pose |= writes_pose(op);
                    }
                    NodeKind::Call(_) => {
                        self.any_global |= !node.pure;
                        self.pose |= !node.pure;
                    }
                }
            }
            _ => {}
        });
    }
}

/// Calls `each` with every step of `steps`, those of nested lists (branch arms, loop
/// bodies, sequence blocks) included: each list in order, nested lists after it.
pub(crate) fn each_step<'s>(steps: &'s [CStep], mut each: impl FnMut(&'s CStep)) {
    let mut lists: Vec<&[CStep]> = vec![steps];
    while let Some(list) = lists.pop() {
        for s in list {
            each(s);
            match s {
                CStep::Branch {
                    then, otherwise, ..
                } => {
                    lists.push(then);
                    lists.push(otherwise);
                }
                CStep::ForEach { body, .. } | CStep::For { body, .. } => lists.push(body),
                CStep::Sequence(blocks) => lists.extend(blocks.iter().map(Vec::as_slice)),
                CStep::Set { .. } | CStep::Exec(_) | CStep::Return(_) => {}
            }
        }
    }
}

/// Calls `each` with the arguments `step` reads itself: a `Set`'s value, a branch's
/// condition, a loop's items or count, a `Return`'s values (not an exec node's inputs, nor
/// what nested steps read).
fn step_args(step: &CStep, mut each: impl FnMut(&crate::check::Arg)) {
    match step {
        CStep::Set { arg, .. } => each(arg),
        CStep::Branch { condition, .. } => each(condition),
        CStep::ForEach { items, .. } => each(items),
        CStep::For { count, .. } => each(count),
        CStep::Return(values) => values.iter().for_each(|(_, a)| each(a)),
        CStep::Exec(_) | CStep::Sequence(_) => {}
    }
}

/// The pure nodes of `body` that `steps` (nested lists included) pull, with everything
/// they depend on, in increasing index order.
pub(crate) fn pulled_by(body: &Body, steps: &[CStep]) -> Vec<usize> {
    let mut roots = Vec::new();
    let mut arg = |a: &crate::check::Arg| {
        if let Src::Node { node, .. } = a.src {
            roots.push(node);
        }
    };
    each_step(steps, |s| match s {
        CStep::Exec(n) => body.nodes[*n].inputs.iter().for_each(&mut arg),
        _ => step_args(s, &mut arg),
    });
    let mut seen = vec![false; body.nodes.len()];
    let mut out = Vec::new();
    while let Some(n) = roots.pop() {
        if seen[n] || !body.nodes[n].pure {
            continue;
        }
        seen[n] = true;
        out.push(n);
        for a in &body.nodes[n].inputs {
            if let Src::Node { node, .. } = a.src {
                roots.push(node);
            }
        }
    }
    out.sort_unstable();
    out
}

/// Memoised [`Reads`] of every node of every body, and of whole function bodies.
///
/// A bit matrix per body: a value reads what the values it pulls read, so each node's reads
/// are the union of its inputs', and a union of rows is a few word operations with nothing
/// to allocate, sort or free.
#[derive(Default)]
pub(crate) struct ReadsTable {
    /// Per body (the graph first, then each function), once laid out.
    bodies: Vec<Option<BodyReads>>,
    /// Per function: the graph variables (a row's first `global_words` words) and the
    /// [`POSE`] and [`STATEFUL`] flags its whole body reads, for calls of it.
    functions: Vec<Option<(Vec<u64>, u8)>>,
}

/// The reads of one body's nodes: row `n` of `rows` (`width` words) has bit `g` for graph
/// variable `g`, bit [`BodyReads::var_bit`] for each local, bit [`BodyReads::exec_bit`] for
/// each exec node whose outputs the node reads.
struct BodyReads {
    /// Words per row.
    width: usize,
    /// Words holding the graph variables' bits, first in a row.
    global_words: usize,
    /// The bit of local 0.
    locals_at: usize,
    /// The bit of the first exec node's outputs.
    execs_at: usize,
    /// Per node: an exec node's number among the body's exec nodes (in node order), so that
    /// a row has bits for those only; `None` for a pure node (no value reads its outputs as
    /// an exec node's: it reads what they read).
    exec_number: Vec<Option<u32>>,
    /// The rows, node after node.
    rows: Vec<u64>,
    /// Per node: [`KNOWN`] once its row is filled in, and the [`Reads`] flags.
    flags: Vec<u8>,
    /// Built on first use (see [`Readers`]).
    readers: Option<Readers>,
}

impl BodyReads {
    fn new(globals: usize, b: &Body) -> Self {
        let global_words = globals.div_ceil(64);
        let locals_at = 64 * global_words;
        let execs_at = locals_at + 64 * b.locals.len().div_ceil(64);
        let mut execs = 0;
        let exec_number = b
            .nodes
            .iter()
            .map(|node| {
                let number = (!node.pure).then_some(execs);
                execs += u32::from(!node.pure);
                number
            })
            .collect();
        let width = execs_at / 64 + (execs as usize).div_ceil(64);
        Self {
            width,
            global_words,
            locals_at,
            execs_at,
            exec_number,
            rows: vec![0; width * b.nodes.len()],
            flags: vec![0; b.nodes.len()],
            readers: None,
        }
    }

    /// The bit of variable or local `v`.
    fn var_bit(&self, v: VarRef) -> usize {
        match v {
            VarRef::Global(g) => g,
            VarRef::Local(l) => self.locals_at + l,
        }
    }

    /// The bit of exec node `n`'s outputs (`None` for a pure node).
    fn exec_bit(&self, n: usize) -> Option<usize> {
        self.exec_number[n].map(|k| self.execs_at + k as usize)
    }

    fn set(&mut self, n: usize, b: usize) {
        self.rows[n * self.width + b / 64] |= 1 << (b % 64);
    }

    /// Adds row `from` (another node's) to row `n`.
    fn add_row(&mut self, n: usize, from: usize) {
        let w = self.width;
        for k in 0..w {
            self.rows[n * w + k] |= self.rows[from * w + k];
        }
    }

    fn reads(&self, n: usize) -> Reads<'_> {
        Reads {
            row: &self.rows[n * self.width..(n + 1) * self.width],
            flags: self.flags[n] & !KNOWN,
            body: self,
        }
    }
}

/// For everything a step may write, the pure nodes of one body whose values read it: the
/// inverse of [`BodyReads`]. Forgetting what a step changed is then a few word operations
/// per thing written, not a test of every kept value against it.
struct Readers {
    /// The nodes that read the pose.
    pose: FixedBitSet,
    /// The nodes that read any graph variable.
    any_global: FixedBitSet,
    /// Per bit of a row, the nodes that read it (empty when none does; shorter when none
    /// reads the last bits).
    by_bit: Vec<FixedBitSet>,
}

impl ReadsTable {
    /// What node `n` of `body` (`None`: the graph) reads. Iterative, so long chains of pure
    /// nodes cannot overflow the stack; the checker guarantees they are acyclic.
    pub(crate) fn node(&mut self, checked: &Checked, body: Option<usize>, n: usize) -> Reads<'_> {
        let at = self.fill(checked, body, n);
        self.bodies[at].as_ref().expect("laid out").reads(n)
    }

    /// Removes from `kept` (pure nodes of `body` whose values are kept) those that `writes`
    /// may change: the nodes `n` with `writes.touch(&self.node(checked, body, n))`.
    pub(crate) fn forget(
        &mut self,
        checked: &Checked,
        body: Option<usize>,
        writes: &Writes,
        kept: &mut FixedBitSet,
    ) {
        if writes.everything {
            kept.clear();
            return;
        }
        let b = self.readers(checked, body);
        let r = b.readers.as_ref().expect("built");
        let mut forget = |bit: usize| {
            if let Some(set) = r.by_bit.get(bit) {
                kept.difference_with(set);
            }
        };
        writes
            .execs
            .iter()
            .filter_map(|&e| b.exec_bit(e))
            .for_each(&mut forget);
        writes.vars.iter().for_each(|&v| forget(b.var_bit(v)));
        if writes.pose {
            kept.difference_with(&r.pose);
        }
        if writes.any_global {
            kept.difference_with(&r.any_global);
        }
    }

    /// The reads of `body` with its [`Readers`], built on first use from the rows of its
    /// pure nodes.
    fn readers(&mut self, checked: &Checked, body: Option<usize>) -> &BodyReads {
        let b = body_of(checked, body);
        let len = b.nodes.len();
        let at = self.lay_out(checked, body);
        if self.bodies[at]
            .as_ref()
            .is_some_and(|b| b.readers.is_none())
        {
            for n in (0..len).filter(|&n| b.nodes[n].pure) {
                self.fill(checked, body, n);
            }
            let reads = self.bodies[at].as_mut().expect("laid out");
            let mut r = Readers {
                pose: FixedBitSet::with_capacity(len),
                any_global: FixedBitSet::with_capacity(len),
                by_bit: Vec::new(),
            };
            for n in (0..len).filter(|&n| b.nodes[n].pure) {
                let row = &reads.rows[n * reads.width..(n + 1) * reads.width];
                r.pose.set(n, reads.flags[n] & POSE != 0);
                r.any_global
                    .set(n, row[..reads.global_words].iter().any(|&w| w != 0));
                for (k, &word) in row.iter().enumerate() {
                    let mut word = word;
                    while word != 0 {
                        let bit = 64 * k + word.trailing_zeros() as usize;
                        word &= word - 1;
                        if r.by_bit.len() <= bit {
                            r.by_bit.resize_with(bit + 1, FixedBitSet::new);
                        }
                        if r.by_bit[bit].is_empty() {
                            r.by_bit[bit].grow(len);
                        }
                        r.by_bit[bit].insert(n);
                    }
                }
            }
            reads.readers = Some(r);
        }
        self.bodies[at].as_ref().expect("laid out")
    }

    /// The index of `body`'s [`BodyReads`], laid out (all rows unknown) on first use.
    fn lay_out(&mut self, checked: &Checked, body: Option<usize>) -> usize {
        let at = body.map_or(0, |f| f + 1);
        if self.bodies.len() <= at {
            self.bodies.resize_with(at + 1, || None);
        }
        if self.bodies[at].is_none() {
            self.bodies[at] = Some(BodyReads::new(
                checked.globals.len(),
                body_of(checked, body),
            ));
        }
        at
    }

    /// Works out the row of node `n` of `body`, and of the pure nodes it pulls, unless
    /// known; returns the body's index in `bodies`.
    fn fill(&mut self, checked: &Checked, body: Option<usize>, n: usize) -> usize {
        let at = self.lay_out(checked, body);
        if self.bodies[at].as_ref().expect("laid out").flags[n] & KNOWN != 0 {
            return at;
        }
        let b = body_of(checked, body);
        let mut stack = vec![(n, false)];
        while let Some((m, inputs_done)) = stack.pop() {
            let node = &b.nodes[m];
            if !inputs_done {
                let reads = self.bodies[at].as_ref().expect("laid out");
                if reads.flags[m] & KNOWN != 0 {
                    continue;
                }
                stack.push((m, true));
                for a in &node.inputs {
                    if let Src::Node { node: dep, .. } = a.src
                        && b.nodes[dep].pure
                        && reads.flags[dep] & KNOWN == 0
                    {
                        stack.push((dep, false));
                    }
                }
                continue;
            }
            // Defensive: only a cycle, which the checker rejects, brings a node here twice.
            if self.bodies[at].as_ref().expect("laid out").flags[m] & KNOWN != 0 {
                continue;
            }
            // A call's function first: it fills other bodies.
            let callee = match node.kind {
                NodeKind::Call(f) => Some((f, self.function(checked, f))),
                NodeKind::Builtin(_) => None,
            };
            let reads = self.bodies[at].as_mut().expect("laid out");
            let mut flags = KNOWN;
            for a in &node.inputs {
                match a.src {
                    Src::Global(g) => reads.set(m, reads.var_bit(VarRef::Global(g))),
                    Src::Local(l) => reads.set(m, reads.var_bit(VarRef::Local(l))),
                    Src::Node { node: dep, .. } if b.nodes[dep].pure => {
                        reads.add_row(m, dep);
                        flags |= reads.flags[dep] & !KNOWN;
                    }
                    // An exec node's outputs change when that node runs again.
                    Src::Node { node: dep, .. } => {
                        let bit = reads.exec_bit(dep).expect("an exec node");
                        reads.set(m, bit);
                    }
                    Src::Loop { .. } => flags |= LOOP_VARS,
                    _ => {}
                }
            }
            if !node.state.is_empty() {
                flags |= STATEFUL;
            }
            if let NodeKind::Builtin(op) = node.kind
                && reads_pose(op)
            {
                flags |= POSE;
            }
            if let Some((f, callee_flags)) = callee {
                let (globals, _) = self.functions[f].as_ref().expect("worked out");
                let row = m * reads.width;
                for (word, g) in reads.rows[row..row + globals.len()].iter_mut().zip(globals) {
                    *word |= g;
                }
                flags |= callee_flags;
            }
            reads.flags[m] = flags;
        }
        at
    }

    /// The graph variables and pose anything in function `f`'s body reads (its locals and
    /// inputs are its own and start afresh at every call), worked out once and kept in
    /// `functions`; returns its [`POSE`] and [`STATEFUL`] flags.
    fn function(&mut self, checked: &Checked, f: usize) -> u8 {
        if let Some(Some((_, flags))) = self.functions.get(f) {
            return *flags;
        }
        // The checker rejects recursion, so this terminates; calls nest only as deep as
        // the functions of the graph do.
        let b = &checked.functions[f];
        let global_words = checked.globals.len().div_ceil(64);
        let mut globals = vec![0u64; global_words];
        let mut flags = 0;
        for n in 0..b.nodes.len() {
            let r = self.node(checked, Some(f), n);
            for (g, w) in globals.iter_mut().zip(r.row) {
                *g |= w;
            }
            // A node's own state and pose reads are in its flags (`fill`).
            flags |= r.flags & (POSE | STATEFUL);
        }
        for_each_step_global(&b.exec, &mut |g| globals[g / 64] |= 1 << (g % 64));
        if self.functions.len() <= f {
            self.functions.resize_with(f + 1, || None);
        }
        self.functions[f] = Some((globals, flags));
        flags
    }
}

fn body_of(checked: &Checked, body: Option<usize>) -> &Body {
    match body {
        None => &checked.graph,
        Some(f) => &checked.functions[f],
    }
}

/// Calls `each` with every graph variable the steps read directly.
fn for_each_step_global(steps: &[CStep], each: &mut impl FnMut(usize)) {
    let mut arg = |a: &crate::check::Arg| {
        if let Src::Global(g) = a.src {
            each(g);
        }
    };
    each_step(steps, |s| step_args(s, &mut arg));
}
