//! Code generation: typed slot layout and a flat instruction list.
//!
//! Each function call site gets its own frame of slots (calls are inlined), so per-call
//! state never aliases. Pure nodes are emitted in front of the first step that needs them,
//! and their values are kept for later steps for as long as nothing they read changes
//! (see [`Gen::invalidate`]): a `Set` of a variable they read, a mutating node that edits
//! an array they read or moves the pose they read, a call of a function that does either.
//! Before a loop, the pure nodes its body pulls that no iteration can change are emitted
//! once, and values the body cannot change are kept through and after it; values computed
//! in an iteration are not kept into the next one, nor past the loop; after a `Branch`,
//! only values both arms kept are. The result is the same as pulling every pure
//! node again for each step (the semantics of the graph), with each computed once per
//! stretch of code in which its inputs are unchanged.
//!
//! Every instruction is tagged with its origin (the node or step that produced it, see
//! [`strider_vm::InstrOrigin`]) in the program's side table, for profiling and tools.

use crate::Options;
use crate::check::{Arg, Body, CStep, Checked, LoopPart, NodeKind, Src, VarRef};
use crate::reads::{ReadsTable, Writes, each_step, pulled_by};
use fixedbitset::FixedBitSet;
use rustc_hash::{FxHashMap, FxHashSet};
use smallvec::SmallVec;
use std::borrow::Cow;
use std::sync::Arc;
use strider_graph::{EventKind, FunctionDecl, LoadedGraph, Loc, NodeDecl, Step};
use strider_nodes::{Elem, Op, Value, ValueType, registry};
use strider_vm::{
    Event, InstrOrigin, OriginId, OriginKind, OriginScope, PinOwner, PinSlot, Program,
    ProgramBuilder, VariableInfo,
};

/// What the document says about one node of a checked body (same index), for origins.
struct NodeSource<'d> {
    id: Option<&'d str>,
    kind: &'d str,
    /// Described as `path:line:col` only when an origin is made for the node.
    loc: Loc,
}

/// The nodes of a body in the checker's order: declared nodes in file order, then inline
/// nodes of the exec lists in the order the lists are walked (depth first).
fn body_node_sources<'d>(nodes: &'d [NodeDecl], lists: &[&'d [Step]]) -> Vec<NodeSource<'d>> {
    fn walk<'d>(steps: &'d [Step], out: &mut Vec<&'d NodeDecl>) {
        for s in steps {
            match s {
                Step::Node(n) => out.push(n),
                Step::ForEach { body, .. } | Step::For { body, .. } => walk(body, out),
                Step::Branch {
                    then, otherwise, ..
                } => {
                    walk(then, out);
                    walk(otherwise, out);
                }
                Step::Sequence(blocks, _) => {
                    for b in blocks {
                        walk(b, out);
                    }
                }
                Step::Set { .. } | Step::Run(_) | Step::Return { .. } => {}
            }
        }
    }
    let mut decls: Vec<&NodeDecl> = nodes.iter().collect();
    for list in lists {
        walk(list, &mut decls);
    }
    decls
        .into_iter()
        .map(|d| NodeSource {
            id: d.id.as_ref().map(|i| i.name.as_str()),
            kind: &d.kind.name,
            loc: d.loc,
        })
        .collect()
}

/// A step's name and location for its origin.
fn step_source(loaded: &LoadedGraph, step: &CStep, doc: Option<&Step>) -> (String, String) {
    let name = match step {
        CStep::Set { .. } => match doc {
            Some(Step::Set { var, .. }) => format!("Set(\"{}\")", var.name),
            _ => "Set".to_string(),
        },
        CStep::Exec(_) => "Run".to_string(),
        CStep::Branch { .. } => "Branch".to_string(),
        CStep::ForEach { .. } => "ForEach".to_string(),
        CStep::For { .. } => "For".to_string(),
        CStep::Sequence(_) => "Sequence".to_string(),
        CStep::Return(_) => "Return".to_string(),
    };
    let loc = match doc {
        Some(
            Step::Set { loc, .. }
            | Step::Branch { loc, .. }
            | Step::ForEach { loc, .. }
            | Step::For { loc, .. }
            | Step::Sequence(_, loc)
            | Step::Return { loc, .. },
        ) => loaded.sources.describe(*loc),
        Some(Step::Run(id)) => loaded.sources.describe(id.loc),
        Some(Step::Node(n)) => loaded.sources.describe(n.loc),
        None => String::new(),
    };
    (name, loc)
}

/// What makes two constants share a slot: scalars by type and bits (so `-0.0` and `0.0`
/// stay apart), everything else by its text. Bone and text constants carry their source
/// location (for "unknown bone" errors at instantiation), so they are shared only between
/// uses of the same literal.
#[derive(PartialEq, Eq, Hash)]
enum ConstKey {
    Scalar(ValueType, [u32; 10]),
    Text(String),
}

impl ConstKey {
    fn new(value: &Value, location: &str) -> Self {
        let bits = |v: &[f32]| {
            let mut b = [0; 10];
            for (b, v) in b.iter_mut().zip(v) {
                *b = v.to_bits();
            }
            b
        };
        let word = |w: u32| {
            let mut b = [0; 10];
            b[0] = w;
            b
        };
        match value {
            Value::Bool(v) => ConstKey::Scalar(ValueType::Bool, word(u32::from(*v))),
            Value::Int(v) => ConstKey::Scalar(ValueType::Int, word(v.cast_unsigned())),
            Value::Float(v) => ConstKey::Scalar(ValueType::Float, bits(&[*v])),
            Value::Vec3(v) => ConstKey::Scalar(ValueType::Vec3, bits(&v.to_array())),
            Value::Quat(q) => ConstKey::Scalar(ValueType::Quat, bits(&q.to_array())),
            Value::Transform(t) => ConstKey::Scalar(ValueType::Transform, t.to_bits()),
            _ if ConstKey::per_literal(value) => ConstKey::Text(format!("{value:?}@{location}")),
            _ => ConstKey::Text(format!("{value:?}")),
        }
    }

    /// Whether `value` names bones or text, and so is kept apart per literal.
    fn per_literal(value: &Value) -> bool {
        match value {
            Value::Bone(Some(_)) | Value::Name(_) => true,
            Value::Array(Elem::Bone, items) => !items.is_empty(),
            _ => false,
        }
    }
}

/// An instruction's operand slots as the compiler gathers them (inline up to 24).
type Operands = SmallVec<[u32; 24]>;

struct LoopSlots {
    counter: u32,
    element: u32,
    index: u32,
    count: u32,
    /// The loop's own copy of what it iterates (a ForEach's array, a For's count), taken
    /// once before the loop so the body cannot change it.
    snapshot: u32,
}

/// Rows of slot indices laid end to end, one per node of a body (its output slots, or its
/// state slots): one allocation for the body instead of one per node.
#[derive(Default)]
struct Rows {
    slots: Vec<u32>,
    /// Row `n` ends at `slots[ends[n]]` and starts where row `n - 1` ends (row 0 at 0).
    ends: Vec<u32>,
}

impl Rows {
    fn with_capacity(rows: usize) -> Self {
        Rows {
            slots: Vec::with_capacity(rows),
            ends: Vec::with_capacity(rows),
        }
    }

    fn push(&mut self, row: impl IntoIterator<Item = u32>) {
        self.slots.extend(row);
        self.ends.push(self.slots.len() as u32);
    }

    fn len(&self) -> usize {
        self.ends.len()
    }
}

impl std::ops::Index<usize> for Rows {
    type Output = [u32];

    fn index(&self, n: usize) -> &[u32] {
        let start = n.checked_sub(1).map_or(0, |p| self.ends[p] as usize);
        &self.slots[start..self.ends[n] as usize]
    }
}

struct Frame {
    body: Option<usize>,
    /// Each node's output slots.
    node_out: Rows,
    /// Each node's state slots.
    node_state: Rows,
    /// Where the body reads each input: its own slot, or the argument's slot at the call
    /// being emitted (see [`Gen::node_code`]).
    inputs: Vec<u32>,
    /// The inputs' own slots, which a call copies its arguments into.
    own_inputs: Vec<u32>,
    outputs: Vec<u32>,
    /// Where the body reads each local: its own slot, or its default's constant slot for a
    /// local the body never writes.
    locals: Vec<u32>,
    loops: Vec<LoopSlots>,
    callees: FxHashMap<usize, usize>,
    /// The pin table entries of the inputs and locals (functions only), in that order.
    pins: Vec<usize>,
}

/// What a function's body does with its locals and outputs, for the code of a call.
struct CallFacts {
    /// Per local: some step sets it or a mutating node edits it in place.
    local_written: Vec<bool>,
    /// Per output: every way out of the body returns a value for it (the body ends in a
    /// `Return` and every `Return` gives it), so a call need not zero it first.
    output_always_returned: Vec<bool>,
}

impl CallFacts {
    fn of(body: &Body) -> Self {
        let mut writes = Writes::default();
        writes.collect(body, &body.exec);
        let local_written = (0..body.locals.len())
            .map(|l| writes.vars.contains(&VarRef::Local(l)))
            .collect();
        let ends_in_return = matches!(body.exec.last(), Some(CStep::Return(_)));
        let mut returns: Vec<&[(usize, Arg)]> = Vec::new();
        each_step(&body.exec, |step| {
            if let CStep::Return(values) = step {
                returns.push(values);
            }
        });
        let output_always_returned = (0..body.outputs.len())
            .map(|o| ends_in_return && returns.iter().all(|r| r.iter().any(|(i, _)| *i == o)))
            .collect();
        Self {
            local_written,
            output_always_returned,
        }
    }
}

struct Gen<'a> {
    pb: ProgramBuilder,
    checked: &'a Checked,
    globals: Vec<u32>,
    consts: FxHashMap<ConstKey, u32>,
    frames: Vec<Frame>,
    /// For origins: the document.
    loaded: &'a LoadedGraph,
    /// For origins: the function declarations, indexed as `checked.functions`.
    fn_decls: Vec<&'a FunctionDecl>,
    /// Each function's name (as `fn_decls`), shared by its pin table entries.
    fn_names: Vec<Arc<str>>,
    /// For origins: each function's nodes, then the graph's (last).
    node_sources: Vec<Vec<NodeSource<'a>>>,
    /// The event being generated.
    event: Event,
    /// Origin of node `n` of body `f` (`None`: the graph) in an event (`None` in functions).
    node_origins: FxHashMap<(Option<usize>, usize, Option<Event>), OriginId>,
    /// Per frame: the pure nodes whose output slots hold their current value at the point
    /// being emitted.
    avail: Vec<FixedBitSet>,
    /// What each pure node's value depends on.
    reads: ReadsTable,
    /// Per function (as `checked.functions`): what its calls may leave out.
    call_facts: Vec<CallFacts>,
    /// The slots of graph variables and of every function local, by type: an argument held
    /// in one is copied into the function's input (a variable may be set again while the
    /// body runs, or later in the frame, where the inspector would show its new value).
    variable_slots: FxHashSet<(ValueType, u32)>,
    /// The `Return` being emitted is its body's last step (see [`Gen::exec_list`]).
    tail_return: bool,
    /// [`Gen::pure_closure`]'s work stack, kept for the next call.
    closure_stack: Vec<(usize, bool)>,
}

pub(crate) fn generate(loaded: &LoadedGraph, checked: &Checked, options: Options) -> Program {
    let name = if loaded.main.name.is_empty() {
        loaded
            .sources
            .path(loaded.main.file)
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned())
            .unwrap_or_default()
    } else {
        loaded.main.name.clone()
    };
    // The document's side of what the checker indexed, for instruction origins: functions
    // of every file in file order (as the checker numbers them), event lists concatenated.
    let fn_decls: Vec<&FunctionDecl> = std::iter::once(&loaded.main)
        .chain(&loaded.libraries)
        .flat_map(|g| &g.functions)
        .collect();
    let event_steps = |kind: EventKind| -> Vec<Step> {
        loaded
            .main
            .events
            .iter()
            .filter(|e| e.kind == kind)
            .flat_map(|e| e.steps.iter().cloned())
            .collect()
    };
    let (construction_doc, forward_doc) = (
        event_steps(EventKind::Construction),
        event_steps(EventKind::Forward),
    );
    let fn_names = fn_decls
        .iter()
        .map(|f| Arc::from(f.name.name.as_str()))
        .collect();
    let mut node_sources: Vec<Vec<NodeSource<'_>>> = fn_decls
        .iter()
        .map(|f| body_node_sources(&f.nodes, &[&f.exec]))
        .collect();
    node_sources.push(body_node_sources(
        &loaded.main.nodes,
        &[&construction_doc, &forward_doc],
    ));
    // Every node of every function once, and the graph's once in each event.
    let node_origins = checked
        .functions
        .iter()
        .map(|f| f.nodes.len())
        .sum::<usize>()
        + 2 * checked.graph.nodes.len();
    let mut pb = ProgramBuilder::new(&name);
    // The nodes' origins (some nodes are never emitted), and the steps' (fewer).
    pb.reserve_origins(node_origins + node_origins / 4);
    let mut g = Gen {
        pb,
        checked,
        globals: Vec::new(),
        consts: FxHashMap::default(),
        frames: Vec::new(),
        loaded,
        fn_names,
        fn_decls,
        node_sources,
        event: Event::Construction,
        node_origins: FxHashMap::with_capacity_and_hasher(node_origins, Default::default()),
        avail: Vec::new(),
        reads: ReadsTable::default(),
        call_facts: checked.functions.iter().map(CallFacts::of).collect(),
        variable_slots: FxHashSet::default(),
        tail_return: false,
        closure_stack: Vec::new(),
    };
    for v in &checked.globals {
        let slot = g.pb.alloc(v.ty);
        g.variable_slots.insert((v.ty, slot));
        g.pb.write(slot, &v.default, &v.location);
        g.globals.push(slot);
        g.pb.variable(VariableInfo {
            name: v.name.clone(),
            ty: v.ty,
            slot,
            default: v.default.clone(),
            tunable: v.tunable,
            location: v.location.clone(),
        });
    }
    let top = g.frame(None, Vec::new());
    g.avail = (0..g.frames.len())
        .map(|f| FixedBitSet::with_capacity(g.body(f).nodes.len()))
        .collect();
    for (steps, doc, event) in [
        (
            &checked.graph.construction,
            &construction_doc,
            Event::Construction,
        ),
        (&checked.graph.forward, &forward_doc, Event::Forward),
    ] {
        g.event = event;
        g.avail.iter_mut().for_each(FixedBitSet::clear);
        let entry = g.pb.here();
        if event == Event::Construction {
            g.pb.set_construction_entry(entry);
        } else {
            g.pb.set_forward_entry(entry);
        }
        g.exec_list(top, steps, doc);
        let origin = g.pb.intern_origin(InstrOrigin {
            kind: OriginKind::Step,
            node_id: None,
            node_type: "End".to_string(),
            scope: OriginScope::Event(event),
            location: String::new(),
        });
        g.pb.set_origin(Some(origin));
        g.pb.emit(Op::End, &[]);
        g.pb.set_origin(None);
    }
    if options.keep_pin_values {
        g.pb.finish()
    } else {
        g.pb.finish_sharing_slots()
    }
}

impl<'a> Gen<'a> {
    /// The scope origins of `frame` get: its function, or the event being generated.
    fn scope(&self, frame: usize) -> OriginScope {
        match self.frames[frame].body {
            Some(f) => OriginScope::Function(self.fn_decls[f].name.name.clone()),
            None => OriginScope::Event(self.event),
        }
    }

    /// The origin of node `n` of `frame` (interned once per body and event).
    fn node_origin(&mut self, frame: usize, n: usize) -> OriginId {
        let body = self.frames[frame].body;
        let key = (body, n, body.is_none().then_some(self.event));
        if let Some(&id) = self.node_origins.get(&key) {
            return id;
        }
        let sources = &self.node_sources[body.unwrap_or(self.node_sources.len() - 1)];
        let (node_id, node_type, location) = match sources.get(n) {
            Some(src) => (
                src.id.map(str::to_string),
                src.kind.to_string(),
                self.loaded.sources.describe(src.loc),
            ),
            None => (None, "?".to_string(), String::new()),
        };
        let kind = match self.body(frame).nodes[n].kind {
            NodeKind::Builtin(_) => OriginKind::Node,
            NodeKind::Call(_) => OriginKind::Call,
        };
        let origin = InstrOrigin {
            kind,
            node_id,
            node_type,
            scope: self.scope(frame),
            location,
        };
        // Each key gets its origin once, and no step's origin equals a node's.
        let id = self.pb.add_origin(origin);
        self.node_origins.insert(key, id);
        id
    }

    /// Sets the origin of a step of `frame` for what is emitted next; returns the previous.
    fn enter_step(&mut self, frame: usize, step: &CStep, doc: Option<&Step>) -> Option<OriginId> {
        let (node_type, location) = step_source(self.loaded, step, doc);
        let origin = InstrOrigin {
            kind: OriginKind::Step,
            node_id: None,
            node_type,
            scope: self.scope(frame),
            location,
        };
        let id = self.pb.intern_origin(origin);
        self.pb.set_origin(Some(id))
    }

    fn body(&self, frame: usize) -> &'a Body {
        match self.frames[frame].body {
            None => &self.checked.graph,
            Some(f) => &self.checked.functions[f],
        }
    }

    /// Output pin names of node `n` of body `body` (`None`: the graph), for the pin table.
    fn output_names(&self, body: Option<usize>, n: usize) -> Vec<Cow<'static, str>> {
        let node = match body {
            None => &self.checked.graph.nodes[n],
            Some(f) => &self.checked.functions[f].nodes[n],
        };
        match node.kind {
            NodeKind::Call(f) => self.fn_decls[f]
                .outputs
                .iter()
                .map(|p| Cow::Owned(p.name.name.clone()))
                .collect(),
            NodeKind::Builtin(op) => {
                let sources = &self.node_sources[body.unwrap_or(self.node_sources.len() - 1)];
                sources
                    .get(n)
                    .and_then(|src| registry().get(src.kind))
                    .and_then(|spec| spec.overloads.iter().find(|o| o.op == op))
                    .map(|o| o.outputs.iter().map(|p| Cow::Borrowed(p.name)).collect())
                    .unwrap_or_default()
            }
        }
    }

    /// Records the slots of a body instance's inputs and locals (functions) and of its node
    /// outputs in the program's pin table.
    fn record_pins(&mut self, frame: usize, path: &[u32]) {
        let body = self.frames[frame].body;
        let function = body.map(|f| self.fn_names[f].clone());
        let mut entries: Vec<(PinOwner, Cow<'static, str>, ValueType, u32)> = Vec::new();
        if let Some(f) = body {
            let decl = self.fn_decls[f];
            let b = &self.checked.functions[f];
            for (i, p) in decl.inputs.iter().enumerate() {
                entries.push((
                    PinOwner::FunctionInput,
                    Cow::Owned(p.name.name.clone()),
                    b.inputs[i],
                    self.frames[frame].inputs[i],
                ));
            }
            for (i, l) in decl.locals.iter().enumerate() {
                entries.push((
                    PinOwner::Local,
                    Cow::Owned(l.name.name.clone()),
                    b.locals[i].0,
                    self.frames[frame].locals[i],
                ));
            }
        }
        for n in 0..self.frames[frame].node_out.len() {
            let names = self.output_names(body, n);
            let types = &self.body(frame).nodes[n].outputs;
            let slots = &self.frames[frame].node_out[n];
            for (name, (&slot, &ty)) in names.into_iter().zip(slots.iter().zip(types)) {
                entries.push((PinOwner::NodeOutput(n as u32), name, ty, slot));
            }
        }
        for (owner, pin, ty, slot) in entries {
            let is_variable = matches!(owner, PinOwner::FunctionInput | PinOwner::Local);
            let index = self.pb.pin_slot(PinSlot {
                call_path: path.to_vec(),
                function: function.clone(),
                owner,
                pin,
                ty,
                slot,
            });
            if is_variable {
                self.frames[frame].pins.push(index);
            }
        }
    }

    /// Allocates the slots of one instance of a body (and, recursively, of its calls);
    /// `path` is the call path that reaches it (see [`PinSlot::call_path`]).
    fn frame(&mut self, function: Option<usize>, path: Vec<u32>) -> usize {
        let body = match function {
            None => &self.checked.graph,
            Some(f) => &self.checked.functions[f],
        };
        let inputs: Vec<u32> = body.inputs.iter().map(|&t| self.pb.alloc(t)).collect();
        let outputs = body.outputs.iter().map(|&t| self.pb.alloc(t)).collect();
        let locals: Vec<u32> = body
            .locals
            .iter()
            .map(|(t, _, _)| self.pb.alloc(*t))
            .collect();
        if function.is_some() {
            for (&(t, _, _), &slot) in body.locals.iter().zip(&locals) {
                self.variable_slots.insert((t, slot));
            }
        }
        let loops = body
            .loops
            .iter()
            .map(|l| LoopSlots {
                counter: self.pb.alloc(ValueType::Int),
                element: self.pb.alloc(l.element),
                index: self.pb.alloc(ValueType::Int),
                count: self.pb.alloc(ValueType::Int),
                snapshot: match (l.is_for, l.element.elem()) {
                    (false, Some(e)) => self.pb.alloc(ValueType::Array(e)),
                    _ => self.pb.alloc(ValueType::Int),
                },
            })
            .collect();
        let id = self.frames.len();
        self.frames.push(Frame {
            body: function,
            node_out: Rows::default(),
            node_state: Rows::default(),
            own_inputs: inputs.clone(),
            inputs,
            outputs,
            locals,
            loops,
            callees: FxHashMap::default(),
            pins: Vec::new(),
        });
        let node_count = body.nodes.len();
        let mut node_out = Rows::with_capacity(node_count);
        let mut node_state = Rows::with_capacity(node_count);
        for n in 0..node_count {
            let node = &self.body(id).nodes[n];
            let kind = node.kind;
            let out_types = &node.outputs;
            let state_types = &node.state;
            node_state.push(state_types.iter().map(|&t| self.pb.alloc(t)));
            match kind {
                NodeKind::Call(f) => {
                    let mut callee_path = path.clone();
                    callee_path.push(n as u32);
                    let callee = self.frame(Some(f), callee_path);
                    self.frames[id].callees.insert(n, callee);
                    node_out.push(self.frames[callee].outputs.iter().copied());
                }
                NodeKind::Builtin(_) => node_out.push(out_types.iter().map(|&t| self.pb.alloc(t))),
            }
        }
        self.frames[id].node_out = node_out;
        self.frames[id].node_state = node_state;
        self.record_pins(id, &path);
        id
    }

    fn constant(&mut self, value: &Value, location: &str) -> u32 {
        let key = ConstKey::new(value, location);
        if let Some(&s) = self.consts.get(&key) {
            return s;
        }
        let s = self.pb.constant(value, location);
        self.consts.insert(key, s);
        s
    }

    /// The slot holding `arg` (after emitting its Int → Float conversion, if any).
    fn slot(&mut self, frame: usize, arg: &Arg) -> u32 {
        let f = &self.frames[frame];
        let s = match &arg.src {
            Src::Node { node, out } => f.node_out[*node][*out],
            Src::Input(i) => f.inputs[*i],
            Src::Local(i) => f.locals[*i],
            Src::Global(i) => self.globals[*i],
            Src::Loop { lp, part } => {
                let l = &f.loops[*lp];
                match part {
                    LoopPart::Element => l.element,
                    LoopPart::Index => l.index,
                    LoopPart::Count => l.count,
                }
            }
            Src::Const { value, loc } => {
                // Only constants kept apart per literal need their location (bone names are
                // looked up at instantiation and reported with it).
                let location = match loc {
                    Some(l) if ConstKey::per_literal(value) => self.loaded.sources.describe(*l),
                    _ => String::new(),
                };
                self.constant(value, &location)
            }
        };
        if arg.to_float {
            let tmp = self.pb.alloc(ValueType::Float);
            self.pb.emit(Op::IntToFloat, &[s, tmp]);
            tmp
        } else {
            s
        }
    }

    /// Emits the pure nodes `args` depend on that do not hold their current value yet,
    /// then returns the argument slots.
    fn pull(&mut self, frame: usize, args: &[Arg]) -> Operands {
        for a in args {
            if let Src::Node { node, .. } = a.src {
                self.pure_closure(frame, node);
            }
        }
        args.iter().map(|a| self.slot(frame, a)).collect()
    }

    /// Emits pure node `root` after the pure nodes it depends on, in dependency order,
    /// skipping those that hold their current value (see [`Gen::avail`]). Iterative
    /// (post-order with an explicit stack), so long data-flow chains cannot overflow the
    /// stack; the checker guarantees the dependencies are acyclic.
    fn pure_closure(&mut self, frame: usize, root: usize) {
        // The stack is reused across calls; a call nested in `node` takes a new one.
        let mut stack = std::mem::take(&mut self.closure_stack);
        stack.push((root, false));
        while let Some((n, inputs_done)) = stack.pop() {
            if inputs_done {
                self.node(frame, n);
                continue;
            }
            if !self.body(frame).nodes[n].pure || self.avail[frame].put(n) {
                continue;
            }
            stack.push((n, true));
            for a in self.body(frame).nodes[n].inputs.iter().rev() {
                if let Src::Node { node, .. } = a.src
                    && !self.avail[frame].contains(node)
                {
                    stack.push((node, false));
                }
            }
        }
        self.closure_stack = stack;
    }

    /// Before a loop over `body` in `frame`: emits the pure nodes the body pulls that no
    /// iteration can change (they read no loop variable, nothing the body writes, and no
    /// stateful node, whose state must advance where the graph evaluates it), and keeps
    /// only the values the body cannot change. Returns those values: they hold in every
    /// iteration and after the loop, however many times it runs. `writes` is what the body
    /// may change ([`Gen::writes_of`]).
    fn enter_loop(&mut self, frame: usize, body: &[CStep], writes: &Writes) -> FixedBitSet {
        let checked = self.checked;
        let function = self.frames[frame].body;
        let frame_body = match function {
            None => &checked.graph,
            Some(f) => &checked.functions[f],
        };
        for n in pulled_by(frame_body, body) {
            let r = self.reads.node(checked, function, n);
            if !r.loop_vars() && !r.stateful() && !writes.touch(&r) {
                self.pure_closure(frame, n);
            }
        }
        self.forget(frame, writes);
        self.avail[frame].clone()
    }

    /// What running `steps` (nested lists included) in `frame` may change.
    fn writes_of(&self, frame: usize, steps: &[CStep]) -> Writes {
        let mut writes = Writes::default();
        writes.collect(self.body(frame), steps);
        writes
    }

    /// Whether a body of `frame` that may change `writes` ([`Gen::writes_of`]) may change
    /// the value at `src`: a variable or local it sets or edits in place, any graph
    /// variable after an impure call, an exec node's outputs when the body runs it,
    /// anything when a mutating node edits a pure node's output in place. Constants and
    /// function inputs never change while a body runs.
    fn body_may_change(&mut self, frame: usize, src: &Src, writes: &Writes) -> bool {
        writes.everything
            || match src {
                Src::Global(g) => writes.any_global || writes.vars.contains(&VarRef::Global(*g)),
                Src::Local(l) => writes.vars.contains(&VarRef::Local(*l)),
                Src::Node { node, .. } => {
                    // An exec node the body runs; a pure node the body may emit again into
                    // the same slots, after changing what it reads.
                    let (checked, function) = (self.checked, self.frames[frame].body);
                    writes.execs.contains(node)
                        || (self.body(frame).nodes[*node].pure
                            && writes.touch(&self.reads.node(checked, function, *node)))
                }
                Src::Input(_) | Src::Const { .. } => false,
                Src::Loop { .. } => true,
            }
    }

    /// Forgets the kept values of `frame` that `writes` may change.
    fn forget(&mut self, frame: usize, writes: &Writes) {
        let body = self.frames[frame].body;
        // In debug builds (the tests), the readers' index is held to the definition: every
        // kept value whose reads the writes touch, and no other, is forgotten.
        #[cfg(debug_assertions)]
        let expected = {
            let mut kept = self.avail[frame].clone();
            let touched: Vec<usize> = kept
                .ones()
                .filter(|&n| writes.touch(&self.reads.node(self.checked, body, n)))
                .collect();
            touched.into_iter().for_each(|n| kept.set(n, false));
            kept
        };
        self.reads
            .forget(self.checked, body, writes, &mut self.avail[frame]);
        #[cfg(debug_assertions)]
        assert_eq!(
            self.avail[frame], expected,
            "the readers' index forgot other values"
        );
    }

    /// Forgets the kept values of `frame` that `step`, just emitted, may have changed: the
    /// variable a `Set` wrote; for an exec node its outputs, the variables and arrays it
    /// edits in place, the pose if it may move bones, and after an impure call any graph
    /// variable and the pose.
    fn forget_written_by(&mut self, frame: usize, step: &CStep) {
        let writes = self.writes_of(frame, std::slice::from_ref(step));
        self.forget(frame, &writes);
    }

    /// Emits node `n` of `frame` itself; the pure nodes it reads must already be emitted
    /// for this step (see [`Gen::pull`]).
    fn node(&mut self, frame: usize, n: usize) {
        let origin = self.node_origin(frame, n);
        let outer = self.pb.set_origin(Some(origin));
        self.node_code(frame, n);
        self.pb.set_origin(outer);
    }

    /// [`Gen::node`] without setting the origin.
    fn node_code(&mut self, frame: usize, n: usize) {
        let node = &self.body(frame).nodes[n];
        let ins = self.pull(frame, &node.inputs);
        match node.kind {
            NodeKind::Builtin(op) => {
                let mut operands = ins;
                operands.extend_from_slice(&self.frames[frame].node_out[n]);
                operands.extend_from_slice(&self.frames[frame].node_state[n]);
                self.pb.emit(op, &operands);
            }
            NodeKind::Call(f) => {
                let callee = self.frames[frame].callees[&n];
                let checked = self.checked;
                let fbody = &checked.functions[f];
                // An input reads its argument's slot in place unless that slot is a variable
                // (see `variable_slots`); nothing else the caller holds can change while the
                // body runs, and the body cannot write its inputs.
                for (i, &s) in ins.iter().enumerate() {
                    let ty = fbody.inputs[i];
                    let read = if self.variable_slots.contains(&(ty, s)) {
                        let own = self.frames[callee].own_inputs[i];
                        self.pb.emit(Op::Copy(ty), &[s, own]);
                        own
                    } else {
                        s
                    };
                    self.frames[callee].inputs[i] = read;
                    let pin = self.frames[callee].pins[i];
                    self.pb.move_pin_slot(pin, read);
                }
                for (i, &ty) in fbody.outputs.iter().enumerate() {
                    if !self.call_facts[f].output_always_returned[i] {
                        let zero = self.constant(&ty.zero(), "");
                        let to = self.frames[callee].outputs[i];
                        self.pb.emit(Op::Copy(ty), &[zero, to]);
                    }
                }
                // A local the body never writes reads its default's constant in place.
                for (i, (ty, default, location)) in fbody.locals.iter().enumerate() {
                    let from = self.constant(default, location);
                    if self.call_facts[f].local_written[i] {
                        let to = self.frames[callee].locals[i];
                        self.pb.emit(Op::Copy(*ty), &[from, to]);
                    } else {
                        self.frames[callee].locals[i] = from;
                        let pin = self.frames[callee].pins[fbody.inputs.len() + i];
                        self.pb.move_pin_slot(pin, from);
                    }
                }
                // The inputs were just copied: nothing of an earlier run of the body holds.
                self.avail[callee].clear();
                let exec = &self.checked.functions[f].exec;
                let doc = &self.fn_decls[f].exec;
                self.exec_list(callee, exec, doc);
            }
        }
    }

    /// Emits the exec list of a function body or an event, its `Return`s jumping past its
    /// end. A `Return` that is the list's last step has its end next: it jumps nowhere.
    fn exec_list(&mut self, frame: usize, steps: &[CStep], doc: &[Step]) {
        let mut rets = Vec::new();
        match steps.split_last() {
            Some((last @ CStep::Return(_), init)) => {
                self.steps(frame, init, doc, &mut rets);
                self.tail_return = true;
                self.step(frame, last, doc.get(init.len()), &mut rets);
            }
            _ => self.steps(frame, steps, doc, &mut rets),
        }
        let end = self.pb.here();
        for r in rets {
            self.pb.patch(r, 0, end);
        }
    }

    /// Emits `steps`; `doc` is the same list in the document (for origins).
    fn steps(&mut self, frame: usize, steps: &[CStep], doc: &[Step], rets: &mut Vec<u32>) {
        for (i, s) in steps.iter().enumerate() {
            self.step(frame, s, doc.get(i), rets);
        }
    }

    fn step(&mut self, frame: usize, step: &CStep, doc: Option<&Step>, rets: &mut Vec<u32>) {
        let outer = match step {
            CStep::Exec(_) => None,
            _ => Some(self.enter_step(frame, step, doc)),
        };
        self.step_code(frame, step, doc, rets);
        if let Some(outer) = outer {
            self.pb.set_origin(outer);
        }
    }

    /// [`Gen::step`] without setting the origin.
    fn step_code(&mut self, frame: usize, step: &CStep, doc: Option<&Step>, rets: &mut Vec<u32>) {
        match step {
            CStep::Set { target, ty, arg } => {
                let from = self.pull(frame, std::slice::from_ref(arg))[0];
                let to = match target {
                    VarRef::Global(i) => self.globals[*i],
                    VarRef::Local(i) => self.frames[frame].locals[*i],
                };
                self.pb.emit(Op::Copy(*ty), &[from, to]);
                self.forget_written_by(frame, step);
            }
            CStep::Exec(n) => {
                self.node(frame, *n);
                self.forget_written_by(frame, step);
            }
            CStep::Branch {
                condition,
                then,
                otherwise,
            } => {
                let c = self.pull(frame, std::slice::from_ref(condition))[0];
                let (then_doc, else_doc): (&[Step], &[Step]) = match doc {
                    Some(Step::Branch {
                        then: t,
                        otherwise: o,
                        ..
                    }) => (t, o),
                    _ => (&[], &[]),
                };
                let jf = self.pb.emit(Op::JumpIfFalse, &[c, 0]);
                let before = self.avail[frame].clone();
                self.steps(frame, then, then_doc, rets);
                let after_then = std::mem::replace(&mut self.avail[frame], before);
                // Without an else arm the then arm runs on into what follows.
                let j = (!otherwise.is_empty()).then(|| self.pb.emit(Op::Jump, &[0]));
                let else_at = self.pb.here();
                self.pb.patch(jf, 1, else_at);
                self.steps(frame, otherwise, else_doc, rets);
                let end = self.pb.here();
                if let Some(j) = j {
                    self.pb.patch(j, 0, end);
                }
                self.avail[frame].intersect_with(&after_then);
            }
            CStep::ForEach { items, lp, body } => {
                let source = self.pull(frame, std::slice::from_ref(items))[0];
                let elem = items.ty.elem().unwrap_or(Elem::Int);
                let zero = self.constant(&Value::Int(0), "");
                let (counter, element, index, count, arr) = {
                    let l = &self.frames[frame].loops[*lp];
                    (l.counter, l.element, l.index, l.count, l.snapshot)
                };
                // The loop walks its own copy of the array only if the body could change the
                // array it iterates; otherwise the array itself.
                let writes = self.writes_of(frame, body);
                let arr = if self.body_may_change(frame, &items.src, &writes) {
                    self.pb.emit(Op::Copy(items.ty), &[source, arr]);
                    arr
                } else {
                    source
                };
                self.pb.emit(Op::Copy(ValueType::Int), &[zero, counter]);
                let keep = self.enter_loop(frame, body, &writes);
                let head = self.pb.here();
                let next = self.pb.emit(
                    Op::ForEachNext(elem),
                    &[arr, counter, element, index, count, 0],
                );
                let body_doc: &[Step] = match doc {
                    Some(Step::ForEach { body, .. }) => body,
                    _ => &[],
                };
                self.steps(frame, body, body_doc, rets);
                self.pb.emit(Op::Jump, &[head]);
                let exit = self.pb.here();
                self.pb.patch(next, 5, exit);
                self.avail[frame] = keep;
            }
            CStep::For { count, lp, body } => {
                let source = self.pull(frame, std::slice::from_ref(count))[0];
                let zero = self.constant(&Value::Int(0), "");
                let (counter, index, n) = {
                    let l = &self.frames[frame].loops[*lp];
                    (l.counter, l.index, l.snapshot)
                };
                self.pb.emit(Op::Copy(ValueType::Int), &[source, n]);
                self.pb.emit(Op::Copy(ValueType::Int), &[zero, counter]);
                let writes = self.writes_of(frame, body);
                let keep = self.enter_loop(frame, body, &writes);
                let head = self.pb.here();
                let next = self.pb.emit(Op::ForNext, &[counter, n, index, 0]);
                let body_doc: &[Step] = match doc {
                    Some(Step::For { body, .. }) => body,
                    _ => &[],
                };
                self.steps(frame, body, body_doc, rets);
                self.pb.emit(Op::Jump, &[head]);
                let exit = self.pb.here();
                self.pb.patch(next, 3, exit);
                self.avail[frame] = keep;
            }
            CStep::Sequence(blocks) => {
                let docs: &[Vec<Step>] = match doc {
                    Some(Step::Sequence(d, _)) => d,
                    _ => &[],
                };
                for (i, b) in blocks.iter().enumerate() {
                    let block_doc = docs.get(i).map_or(&[][..], Vec::as_slice);
                    self.steps(frame, b, block_doc, rets);
                }
            }
            CStep::Return(values) => {
                // Taken before the values are pulled: a pure call pulled here emits a body
                // of its own, whose `Return`s must not see this one's flag.
                let tail = std::mem::take(&mut self.tail_return);
                for (o, arg) in values {
                    let from = self.pull(frame, std::slice::from_ref(arg))[0];
                    let to = self.frames[frame].outputs[*o];
                    let ty = self.body(frame).outputs[*o];
                    self.pb.emit(Op::Copy(ty), &[from, to]);
                }
                if !tail {
                    let j = self.pb.emit(Op::Jump, &[0]);
                    rets.push(j);
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use std::path::Path;
    use std::sync::Arc;
    use strider_core::{Bone, EmptyWorld, Skeleton, Transform};
    use strider_nodes::{Value, ValueType};
    use strider_vm::{FrameInput, Instance, PinOwner, Program};

    /// `Twice(x)` returns `2·x`; the forward event calls it on 3 and on `var("A")` (7), so
    /// its `doubled` node has one slot per call site.
    const GRAPH: &str = r#"Graph(
        version: 1,
        name: "pins",
        variables: { "A": (type: Float, default: 7.0), "Out1": (type: Float), "Out2": (type: Float) },
        functions: {
            "Twice": (
                inputs: { "x": Float },
                outputs: { "y": Float },
                locals: { "scratch": (type: Float, default: 1.5) },
                nodes: { "doubled": Multiply(a: "x", b: 2.0) },
                exec: [ Return(y: "doubled") ],
            ),
        },
        nodes: {
            "first": Twice(x: 3.0),
            "second": Twice(x: var("A")),
            "sum": Add(a: "first.y", b: "second.y"),
            "parts": BreakVector(value: (1.0, 2.0, 3.0)),
        },
        events: {
            forward: [ Set("Out1", "sum"), Set("Out2", "parts.z") ],
        },
    )"#;

    /// How many of `program`'s instructions are `op`.
    fn count(program: &Program, op: strider_nodes::Op) -> usize {
        program.code().iter().filter(|i| i.op == op).count()
    }

    fn skeleton() -> Arc<Skeleton> {
        Arc::new(
            Skeleton::new(vec![Bone {
                name: "root".to_string(),
                parent: None,
                rest_local: Transform::IDENTITY,
            }])
            .expect("one-bone skeleton"),
        )
    }

    /// `GRAPH` compiled with a slot per pin, as the inspector compiles.
    fn with_pin_values() -> Program {
        let loaded =
            strider_graph::load_graph_str(Path::new("pins.ron"), GRAPH.to_string()).expect("loads");
        let options = crate::Options {
            keep_pin_values: true,
        };
        crate::compile_with(&loaded, options).expect("compiles")
    }

    #[test]
    fn every_call_site_has_its_own_pin_slots() {
        let program = with_pin_values();
        let doubled: Vec<_> = program
            .pin_slots()
            .iter()
            .filter(|p| p.function.as_deref() == Some("Twice") && p.pin == "result")
            .collect();
        assert_eq!(doubled.len(), 2, "one entry per call site: {doubled:?}");
        assert_ne!(doubled[0].slot, doubled[1].slot);
        assert_ne!(doubled[0].call_path, doubled[1].call_path);
        assert!(doubled.iter().all(|p| p.ty == ValueType::Float));
        // Top-level nodes in file order: first (0), second (1), sum (2), parts (3).
        let top = |n: u32, pin: &str| {
            program
                .pin_slot(&[], &PinOwner::NodeOutput(n), pin)
                .unwrap_or_else(|| panic!("node {n} pin {pin}"))
                .clone()
        };
        assert_eq!(top(0, "y").ty, ValueType::Float);
        assert_eq!(top(2, "result").ty, ValueType::Float);
        assert_eq!(top(3, "z").ty, ValueType::Float);
        assert!(
            program
                .pin_slot(&[0], &PinOwner::FunctionInput, "x")
                .is_some()
        );
        assert!(
            program
                .pin_slot(&[1], &PinOwner::Local, "scratch")
                .is_some()
        );
        assert!(
            program
                .pin_slot(&[], &PinOwner::NodeOutput(9), "y")
                .is_none()
        );

        let mut instance = Instance::new(Arc::new(program.clone()), skeleton()).expect("instance");
        instance.run_forward(&FrameInput::default(), &EmptyWorld, false);
        let read = |call_path: &[u32], owner: PinOwner, pin: &str| {
            let p = program.pin_slot(call_path, &owner, pin).expect("entry");
            instance.slots().read(p.ty, p.slot)
        };
        // 3·2 and 7·2 at their call sites; their sum; the vector's z.
        assert_eq!(
            read(&[0], PinOwner::NodeOutput(0), "result"),
            Value::Float(6.0)
        );
        assert_eq!(
            read(&[1], PinOwner::NodeOutput(0), "result"),
            Value::Float(14.0)
        );
        assert_eq!(read(&[0], PinOwner::FunctionInput, "x"), Value::Float(3.0));
        assert_eq!(read(&[1], PinOwner::FunctionInput, "x"), Value::Float(7.0));
        assert_eq!(read(&[], PinOwner::NodeOutput(0), "y"), Value::Float(6.0));
        assert_eq!(read(&[], PinOwner::NodeOutput(1), "y"), Value::Float(14.0));
        assert_eq!(
            read(&[], PinOwner::NodeOutput(2), "result"),
            Value::Float(20.0)
        );
        assert_eq!(read(&[], PinOwner::NodeOutput(3), "z"), Value::Float(3.0));
        assert_eq!(read(&[1], PinOwner::Local, "scratch"), Value::Float(1.5));
    }

    /// `Bump` sets the variable it may be given; `Maybe` returns a value on one path only;
    /// `Either` ends in a branch that returns from both arms; `Wrap`'s final `Return` pulls
    /// `Pick`, which returns early from a branch.
    const CALLS: &str = r#"Graph(
        version: 1,
        name: "calls",
        variables: {
            "A": (type: Float, default: 7.0), "Flag": (type: Bool, default: true),
            "Seen": (type: Float), "Got": (type: Float), "Which": (type: Float),
            "Wrapped": (type: Float),
        },
        functions: {
            "Bump": (
                inputs: { "x": Float },
                outputs: { "y": Float },
                nodes: { "plus": Add(a: "x", b: 1.0) },
                exec: [ Set("A", 100.0), Return(y: "plus") ],
            ),
            "Maybe": (
                inputs: { "flag": Bool },
                outputs: { "v": Float },
                exec: [ Branch(condition: "flag", then: [ Return(v: 5.0) ]) ],
            ),
            "Either": (
                inputs: { "flag": Bool },
                outputs: { "v": Float },
                exec: [
                    Branch(condition: "flag", then: [ Return(v: 1.0) ], else: [ Return(v: 2.0) ]),
                ],
            ),
            "Pick": (
                inputs: { "flag": Bool },
                outputs: { "v": Float },
                exec: [ Branch(condition: "flag", then: [ Return(v: 3.0) ]), Return(v: 4.0) ],
            ),
            "Wrap": (
                inputs: { "flag": Bool },
                outputs: { "w": Float },
                nodes: { "picked": Pick(flag: "flag") },
                exec: [ Return(w: "picked.v") ],
            ),
        },
        nodes: {
            "bump": Bump(x: var("A")),
            "maybe": Maybe(flag: var("Flag")),
            "either": Either(flag: var("Flag")),
            "wrap": Wrap(flag: var("Flag")),
        },
        events: {
            forward: [
                Run("bump"), Set("Seen", "bump.y"), Set("Got", "maybe.v"),
                Set("Which", "either.v"), Set("Wrapped", "wrap.w"),
            ],
        },
    )"#;

    #[test]
    fn calls_copy_only_what_the_body_could_see_change() {
        use strider_nodes::Op;
        // `Twice` never writes its local and returns on its only path; its first call's
        // argument is a constant, its second a variable: only the variable is copied in,
        // besides the two `Return`s and the two `Set`s. Neither call jumps to its end.
        let program = with_pin_values();
        let copies = program
            .code()
            .iter()
            .filter(|i| matches!(i.op, Op::Copy(_)))
            .count();
        assert_eq!(copies, 5, "{:?}", program.code());
        assert!(!program.code().iter().any(|i| i.op == Op::Jump));

        let program =
            Arc::new(crate::compile_str(Path::new("calls.ron"), CALLS).expect("compiles"));
        let mut instance = Instance::new(program.clone(), skeleton()).expect("instance");
        let var = |name: &str| program.variable_id(name).expect("variable");
        instance.run_forward(&FrameInput::default(), &EmptyWorld, false);
        // The body saw A = 7 although it set A to 100 before reading its input.
        assert_eq!(instance.variable(var("Seen")), Value::Float(8.0));
        assert_eq!(instance.variable(var("A")), Value::Float(100.0));
        assert_eq!(instance.variable(var("Got")), Value::Float(5.0));
        assert_eq!(instance.variable(var("Which")), Value::Float(1.0));
        // `Pick`, pulled by `Wrap`'s final `Return`, returns early from its branch.
        assert_eq!(instance.variable(var("Wrapped")), Value::Float(3.0));
        // Leaving without a `Return` gives the output's zero, not the last call's value.
        instance
            .set_variable(var("Flag"), &Value::Bool(false))
            .expect("set");
        instance.run_forward(&FrameInput::default(), &EmptyWorld, false);
        assert_eq!(instance.variable(var("Got")), Value::Float(0.0));
        assert_eq!(instance.variable(var("Which")), Value::Float(2.0));
        assert_eq!(instance.variable(var("Wrapped")), Value::Float(4.0));
    }

    /// Pure values are kept between steps only while what they read is unchanged.
    const REUSE: &str = r#"Graph(
        version: 1,
        name: "reuse",
        variables: {
            "A": (type: Float, default: 1.0),
            "Arr": (type: FloatArray, default: [1.0, 2.0]),
            "Flag": (type: Bool, default: true),
            "B": (type: Float), "C": (type: Float), "D": (type: Float), "E": (type: Float),
            "F": (type: Float), "G": (type: Float), "P1": (type: Float), "P2": (type: Float),
            "H": (type: Float), "K": (type: Float),
        },
        nodes: {
            "twice": Multiply(a: var("A"), b: 2.0),
            "trace": SphereTrace(start: (0.0, 0.0, 100.0), end: (0.0, 0.0, -100.0), radius: 5.0),
            "first": At(array: var("Arr"), index: 0),
            "pelvis": GetTransform(bone: bone("root"), space: Global),
            "parts": BreakTransform(value: "pelvis"),
            "pz": BreakVector(value: "parts.translation"),
            "moved": MakeTransform(translation: (0.0, 0.0, 5.0)),
            "plus_one": Add(a: var("A"), b: 1.0),
        },
        events: {
            forward: [
                Set("B", "twice"),
                Set("A", 5.0),
                Set("C", "twice"),
                Set("D", "trace.distance"),
                Set("E", "trace.distance"),
                Set("F", "first"),
                SetAt(array: var("Arr"), index: 0, value: 7.0),
                Set("G", "first"),
                Set("P1", "pz.z"),
                SetTransform(bone: bone("root"), value: "moved", space: Global),
                Set("P2", "pz.z"),
                Set("H", "plus_one"),
                Branch(condition: var("Flag"), then: [Set("A", 0.5)]),
                Set("K", "plus_one"),
            ],
        },
    )"#;

    #[test]
    fn pure_values_are_kept_only_while_their_inputs_are_unchanged() {
        use strider_nodes::Op;
        let program = crate::compile_str(Path::new("reuse.ron"), REUSE).expect("compiles");
        // Read by two steps with nothing in between that it reads: traced once.
        let traces = count(&program, Op::SphereTrace);
        assert_eq!(traces, 1);
        let mut instance = Instance::new(Arc::new(program.clone()), skeleton()).expect("instance");
        instance.run_forward(&FrameInput::default(), &EmptyWorld, false);
        let get = |name: &str| instance.variable(program.variable_id(name).expect(name));
        // A = 1, then 5: `twice` is computed again after the Set.
        assert_eq!(get("B"), Value::Float(2.0));
        assert_eq!(get("C"), Value::Float(10.0));
        // A miss reports the trace's length: 200.
        assert_eq!(get("D"), Value::Float(200.0));
        assert_eq!(get("E"), Value::Float(200.0));
        // SetAt edits the array in place: `first` is read again.
        assert_eq!(get("F"), Value::Float(1.0));
        assert_eq!(get("G"), Value::Float(7.0));
        // SetTransform moves the bone: the pose is read again.
        assert_eq!(get("P1"), Value::Float(0.0));
        assert_eq!(get("P2"), Value::Float(5.0));
        // `plus_one` (A = 5: 6) is kept by the empty else arm but not by the then arm, which
        // sets A = 0.5: after the branch it is computed again (1.5).
        assert_eq!(get("H"), Value::Float(6.0));
        assert_eq!(get("K"), Value::Float(1.5));
    }

    /// A loop body's invariant pure nodes run once, before the loop; what the body
    /// changes is still read afresh in every iteration.
    const HOIST: &str = r#"Graph(
        version: 1,
        name: "hoist",
        variables: {
            "Sum": (type: Float), "Last": (type: Float),
            "Scale": (type: Float, default: 2.0),
        },
        nodes: {
            "probe": SphereTrace(start: (0.0, 0.0, 100.0), end: (0.0, 0.0, -100.0), radius: 5.0),
            "step": Multiply(a: "probe.distance", b: var("Scale")),
            "sum": Add(a: var("Sum"), b: "step"),
            "k": ToFloat(value: "i"),
            "last": Add(a: "k", b: "step"),
        },
        events: {
            forward: [
                Set("Sum", 0.0),
                For(count: 3, index: "i", body: [
                    Set("Sum", "sum"),
                    Set("Last", "last"),
                ]),
            ],
        },
    )"#;

    #[test]
    fn loop_invariant_pure_nodes_run_once_before_the_loop() {
        use strider_nodes::Op;
        let program = crate::compile_str(Path::new("hoist.ron"), HOIST).expect("compiles");
        let code = program.code();
        let trace = code.iter().position(|i| i.op == Op::SphereTrace);
        let head = code.iter().position(|i| i.op == Op::ForNext);
        assert_eq!(count(&program, Op::SphereTrace), 1);
        assert!(
            trace < head,
            "the trace is emitted before the loop: {trace:?} {head:?}"
        );
        let mut instance = Instance::new(Arc::new(program.clone()), skeleton()).expect("instance");
        instance.run_forward(&FrameInput::default(), &EmptyWorld, false);
        let get = |name: &str| instance.variable(program.variable_id(name).expect(name));
        // A miss reports the trace's length, 200; step = 400. Sum is read afresh in each
        // iteration (3 × 400); the last iteration's index is 2.
        assert_eq!(get("Sum"), Value::Float(1200.0));
        assert_eq!(get("Last"), Value::Float(402.0));
    }

    /// A ForEach walks a copy of its array only when its body could change the array: here
    /// the first loop's body sets only a float, the second's appends to the array it walks.
    const SNAPSHOTS: &str = r#"Graph(
        version: 1,
        name: "snapshots",
        variables: {
            "Items": (type: FloatArray, default: [1.0, 2.0, 3.0]),
            "Grow":  (type: FloatArray, default: [1.0]),
            "Sum":   (type: Float),
        },
        nodes: {
            "sum": Add(a: var("Sum"), b: "x"),
        },
        events: {
            forward: [
                Set("Sum", 0.0),
                ForEach(items: var("Items"), element: "x", body: [ Set("Sum", "sum") ]),
                ForEach(items: var("Grow"), element: "g", body: [
                    Append(array: var("Grow"), value: 2.0),
                ]),
            ],
        },
    )"#;

    #[test]
    fn a_loop_copies_its_array_only_when_its_body_may_change_it() {
        use strider_nodes::{Elem, Op};
        let program = crate::compile_str(Path::new("snapshots.ron"), SNAPSHOTS).expect("compiles");
        let copies = count(&program, Op::Copy(ValueType::Array(Elem::Float)));
        assert_eq!(copies, 1, "only the loop over Grow copies its array");
        let mut instance = Instance::new(Arc::new(program.clone()), skeleton()).expect("instance");
        instance.run_forward(&FrameInput::default(), &EmptyWorld, false);
        let get = |name: &str| instance.variable(program.variable_id(name).expect(name));
        assert_eq!(get("Sum"), Value::Float(6.0));
        // The loop over Grow ran once, for the one item it had when it started.
        let grown = Value::Array(Elem::Float, vec![Value::Float(1.0), Value::Float(2.0)]);
        assert_eq!(get("Grow"), grown);
    }

    /// A mutating node edits only its array target in place: a scalar it reads, from a
    /// pure node or a variable, ends no kept value, so invariant values are hoisted out of
    /// a loop whose body edits an array, and kept after it.
    const HOIST_PAST_EDITS: &str = r#"Graph(
        version: 1,
        name: "hoist_past_edits",
        variables: {
            "Arr": (type: FloatArray, default: [0.0, 0.0, 0.0]),
            "Scale": (type: Float, default: 2.0),
            "Out": (type: Float),
            "First": (type: Float),
        },
        nodes: {
            "probe": SphereTrace(start: (0.0, 0.0, 100.0), end: (0.0, 0.0, -100.0), radius: 5.0),
            "step": Multiply(a: "probe.distance", b: var("Scale")),
            "k": ToFloat(value: "i"),
            "value": Add(a: "k", b: "step"),
            "half": Multiply(a: "step", b: 0.5),
            "first": At(array: var("Arr"), index: 0),
        },
        events: {
            forward: [
                Set("First", "first"),
                For(count: 3, index: "i", body: [
                    SetAt(array: var("Arr"), index: "i", value: "value"),
                ]),
                Set("Out", "half"),
                Set("First", "first"),
            ],
        },
    )"#;

    #[test]
    fn array_edits_end_only_the_values_that_read_the_array() {
        use strider_nodes::Op;
        let program = crate::compile_str(Path::new("hoist_past_edits.ron"), HOIST_PAST_EDITS)
            .expect("compiles");
        let code = program.code();
        let trace = code.iter().position(|i| i.op == Op::SphereTrace);
        let head = code.iter().position(|i| i.op == Op::ForNext);
        assert_eq!(
            count(&program, Op::SphereTrace),
            1,
            "traced once: before the loop, and kept after it"
        );
        assert!(trace < head, "{trace:?} {head:?}");
        // `first` reads the array the loop edits: read again after it.
        assert_eq!(count(&program, Op::ArrayAt(strider_nodes::Elem::Float)), 2);
        let mut instance = Instance::new(Arc::new(program.clone()), skeleton()).expect("instance");
        instance.run_forward(&FrameInput::default(), &EmptyWorld, false);
        let get = |name: &str| instance.variable(program.variable_id(name).expect(name));
        // A miss reports the trace's length, 200; step = 400; the elements 400, 401, 402.
        assert_eq!(
            get("Arr"),
            Value::Array(
                strider_nodes::Elem::Float,
                vec![
                    Value::Float(400.0),
                    Value::Float(401.0),
                    Value::Float(402.0)
                ]
            )
        );
        assert_eq!(get("Out"), Value::Float(200.0));
        assert_eq!(get("First"), Value::Float(400.0));
    }
}
