//! [`Program`]: the compiled, immutable form of a graph, and [`ProgramBuilder`], the
//! compiler's way of making one.

use crate::sharing::Layouts;
use crate::slots::{ScalarLens, Slots};
use rustc_hash::FxHashMap;
use std::borrow::Cow;
use std::fmt;
use std::sync::Arc;
use strider_nodes::{Op, Operand, Value, ValueType};

/// One instruction: an op and where its operands start in [`Program::operands`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Instr {
    /// What to do.
    pub op: Op,
    /// Offset of the first operand.
    pub args: u32,
}

/// Identifies a graph variable of a program (stable for the program's lifetime).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct VariableId(pub u32);

/// A graph variable as the host and the inspector see it.
#[derive(Clone, Debug, PartialEq)]
pub struct VariableInfo {
    /// Name as declared.
    pub name: String,
    /// Type as declared.
    pub ty: ValueType,
    /// Slot of `ty` holding it.
    pub slot: u32,
    /// Value at instantiation.
    pub default: Value,
    /// For tunable variables, the range the file gives (`None` if not tunable; bounds may
    /// be open).
    pub tunable: Option<(Option<f32>, Option<f32>)>,
    /// Where it is declared, `file:line:col`.
    pub location: String,
}

/// Where a bone named in the graph goes once resolved.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BoneSlot {
    /// A bone slot.
    Scalar(u32),
    /// Element `index` of a bone-array slot.
    ArrayElement {
        /// The bone-array slot.
        slot: u32,
        /// Position in the array.
        index: u32,
    },
}

/// A bone named by a literal in the graph; resolved against the skeleton at instantiation.
#[derive(Clone, Debug, PartialEq)]
pub struct BoneLiteral {
    /// The bone name.
    pub name: String,
    /// Where the resolved index goes.
    pub slot: BoneSlot,
    /// Where the name is written, `file:line:col`, and which node and pin.
    pub location: String,
}

/// One of a graph's two events.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Event {
    /// Runs when an instance is created (and on rebind).
    Construction,
    /// Runs every frame.
    Forward,
}

impl fmt::Display for Event {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Event::Construction => "construction",
            Event::Forward => "forward",
        })
    }
}

/// Where the graph element that produced an instruction sits.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum OriginScope {
    /// At the graph's top level, emitted for this event (a top-level pure node used by both
    /// events has one origin per event).
    Event(Event),
    /// In the body of this function (shared by every call site, every event).
    Function(String),
}

impl fmt::Display for OriginScope {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OriginScope::Event(e) => write!(f, "{e}"),
            OriginScope::Function(name) => write!(f, "function `{name}`"),
        }
    }
}

/// What kind of graph element produced an instruction.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OriginKind {
    /// A built-in node (its op, and any Int → Float conversion of its inputs).
    Node,
    /// A function call node: the copies of its arguments, outputs and locals (the callee's
    /// body has origins of its own).
    Call,
    /// A step of an exec list: `Set`, `Branch`, `ForEach`, `For`, `Return`, or the `End`
    /// of an event.
    Step,
}

/// The source-map entry of an instruction: which graph node or step produced it.
///
/// Kept in a side table of the [`Program`] (see [`Program::instruction_origin`]); the
/// executor never reads it.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct InstrOrigin {
    /// Node or step.
    pub kind: OriginKind,
    /// The node's id; `None` for an anonymous inline node and for steps.
    pub node_id: Option<String>,
    /// The node type (`Sin`, `TwoBoneIK`, ...), the function's name for a call, or the step
    /// (`Set`, `Branch`, `ForEach`, `For`, `Return`, `End`).
    pub node_type: String,
    /// The function the node sits in, or the event for the graph's top level.
    pub scope: OriginScope,
    /// Where it is written, `file:line:col`; empty when unknown (`End`).
    pub location: String,
}

impl InstrOrigin {
    /// The node's id, or its type for an anonymous node or a step (for display).
    #[must_use]
    pub fn label(&self) -> &str {
        self.node_id.as_deref().unwrap_or(&self.node_type)
    }
}

impl fmt::Display for InstrOrigin {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match &self.node_id {
            Some(id) => write!(f, "`{id}` ({})", self.node_type)?,
            None => write!(f, "{}", self.node_type)?,
        }
        write!(f, " in {}", self.scope)?;
        if !self.location.is_empty() {
            write!(f, " at {}", self.location)?;
        }
        Ok(())
    }
}

/// What a [`PinSlot`] entry is the value of.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub enum PinOwner {
    /// An output pin of a node of the body: the node's index in its body, in the checker's
    /// order (the body's declared `nodes` in file order, then its inline exec nodes in the
    /// order the exec lists are walked, depth first; for the graph's top level, the
    /// `construction` list before `forward`). A function call node's outputs are the
    /// callee's outputs at that call site.
    NodeOutput(u32),
    /// An input of the function the body belongs to (as copied in by the call).
    FunctionInput,
    /// A local variable of the function the body belongs to.
    Local,
}

/// Where one value of a graph element lives in an instance's slots, at one call site: a
/// side table of the [`Program`] for tools such as the inspector (see
/// [`Program::pin_slots`]); the executor never reads it.
///
/// Function calls are inlined per call site, so a node inside a function has one entry per
/// call path. Inside a loop body the slot holds the value of the last iteration run.
#[derive(Clone, Debug, PartialEq, Eq, Hash)]
pub struct PinSlot {
    /// The call sites from the graph's top level down to the body the value belongs to:
    /// each entry is the index of a call node in the body of the previous one (the first in
    /// the graph's top level), numbered as [`PinOwner::NodeOutput`]. Empty for the top
    /// level.
    pub call_path: Vec<u32>,
    /// The function whose body holds the value; `None` for the graph's top level. Shared by
    /// every entry of the function's bodies.
    pub function: Option<Arc<str>>,
    /// Which element of that body.
    pub owner: PinOwner,
    /// The pin, function input or local variable name: the node table's own for a
    /// built-in node's output, owned otherwise.
    pub pin: Cow<'static, str>,
    /// Its type.
    pub ty: ValueType,
    /// The slot of `ty` holding it.
    pub slot: u32,
}

/// Identifies an entry of a program's origin table ([`Program::origins`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct OriginId(pub u32);

/// Marks an instruction without origin in [`Program`]'s per-instruction origin list.
pub(crate) const NO_ORIGIN: u32 = u32::MAX;

/// A compiled graph: flat instructions, operand slot indices, the initial memory image,
/// and the tables the host needs. Immutable and `Send + Sync`; share it with `Arc`.
#[derive(Clone, Debug)]
pub struct Program {
    pub(crate) name: String,
    pub(crate) code: Vec<Instr>,
    pub(crate) operands: Vec<u32>,
    pub(crate) construction: u32,
    pub(crate) forward: u32,
    pub(crate) initial: Slots,
    pub(crate) texts: Vec<String>,
    pub(crate) bones: Vec<BoneLiteral>,
    pub(crate) variables: Vec<VariableInfo>,
    /// Distinct origins, each once.
    pub(crate) origins: Vec<InstrOrigin>,
    /// Per instruction, an index into `origins` or [`NO_ORIGIN`]. Same length as `code`.
    pub(crate) instr_origins: Vec<u32>,
    /// Per instruction, for a fused one ([`Op::FUSED`]) the origin of its second op, an
    /// index into `origins` or [`NO_ORIGIN`]; empty when nothing was fused.
    pub(crate) second_origins: Vec<u32>,
    /// Where node outputs, function inputs and locals live, per call path (tools only).
    pub(crate) pin_slots: Vec<PinSlot>,
    /// The lengths of `initial`'s scalar arrays, which cover every scalar slot operand (see
    /// [`ProgramBuilder::finish`]).
    pub(crate) scalar_lens: ScalarLens,
    /// Per scalar type, one past the highest slot any instruction writes: the slots from
    /// there on (constants, variables only the host sets) hold the same value before and
    /// after every run, so a batch need not copy them back (slot sharing puts them last).
    pub(crate) written_lens: ScalarLens,
    /// Per scalar type, how many of the first slots an instruction writes and a run may
    /// read before writing (graph variables, state kept from frame to frame): the rest of
    /// `0..written_lens` hold values that live only within a run, which a batch does not
    /// copy (see [`crate::lanes::Copies`]). `written_lens` for a program without slot
    /// sharing.
    pub(crate) kept_lens: ScalarLens,
    /// This program's number, unique among the programs [`ProgramBuilder`] finishes in this
    /// process (a clone keeps it: the same slots and initial values): a batch's lanes
    /// remember whose unwritten slots they hold (see [`crate::lanes::Copies`]).
    pub(crate) id: u64,
    /// Whether an instruction traces the world: only then does a run need the character's
    /// world transform as matrices.
    pub(crate) traces: bool,
    /// The program's [`fingerprint`](crate::native::fingerprint), computed the first time
    /// it is asked for (checking generated code against it) and kept: every instance of
    /// a crowd shares the program, so it is computed once, not once per instance.
    pub(crate) fingerprint: std::sync::OnceLock<u64>,
}

impl Program {
    /// The graph's name.
    #[must_use]
    pub fn name(&self) -> &str {
        &self.name
    }

    /// The instructions, in execution order.
    #[must_use]
    pub fn code(&self) -> &[Instr] {
        &self.code
    }

    /// The operand list that instructions index into.
    #[must_use]
    pub fn operands(&self) -> &[u32] {
        &self.operands
    }

    /// The graph's variables, in declaration order.
    #[must_use]
    pub fn variables(&self) -> &[VariableInfo] {
        &self.variables
    }

    /// The variable called `name`. A linear search: resolve once, then use the id.
    #[must_use]
    pub fn variable_id(&self, name: &str) -> Option<VariableId> {
        self.variables
            .iter()
            .position(|v| v.name == name)
            .map(|i| VariableId(i as u32))
    }

    /// A variable's description.
    #[must_use]
    pub fn variable(&self, id: VariableId) -> &VariableInfo {
        &self.variables[id.0 as usize]
    }

    /// Bone names the graph refers to, with where.
    #[must_use]
    pub fn bone_literals(&self) -> &[BoneLiteral] {
        &self.bones
    }

    /// The initial memory image every instance starts from.
    #[must_use]
    pub fn initial_slots(&self) -> &Slots {
        &self.initial
    }

    /// Which graph node or step produced instruction `pc` (an index into
    /// [`Program::code`]); `None` if out of range or not recorded (a hand-built program).
    #[must_use]
    pub fn instruction_origin(&self, pc: usize) -> Option<&InstrOrigin> {
        self.origin_id(pc).map(|id| &self.origins[id.0 as usize])
    }

    /// The id of instruction `pc`'s origin, for grouping instructions by node.
    #[must_use]
    pub fn origin_id(&self, pc: usize) -> Option<OriginId> {
        match self.instr_origins.get(pc) {
            Some(&i) if i != NO_ORIGIN => Some(OriginId(i)),
            _ => None,
        }
    }

    /// For a fused instruction (two adjacent ops joined into one, [`Op::FUSED`]), the id
    /// of its second op's origin ([`Program::origin_id`] is the first's); `None` for any
    /// other instruction.
    #[must_use]
    pub fn second_origin_id(&self, pc: usize) -> Option<OriginId> {
        match self.second_origins.get(pc) {
            Some(&i) if i != NO_ORIGIN => Some(OriginId(i)),
            _ => None,
        }
    }

    /// The origin table: every distinct origin once, indexed by [`OriginId`].
    #[must_use]
    pub fn origins(&self) -> &[InstrOrigin] {
        &self.origins
    }

    /// An origin by id.
    #[must_use]
    pub fn origin(&self, id: OriginId) -> &InstrOrigin {
        &self.origins[id.0 as usize]
    }

    /// Where every node output, function input and function local lives, per call path,
    /// in the order the compiler allocated them (empty for a hand-built program). For
    /// tools: read a pin's current value with `Slots::read(entry.ty, entry.slot)`. A
    /// program built with [`ProgramBuilder::finish_sharing_slots`] (the compiler's
    /// default) lists only the values that kept a slot of their own.
    #[must_use]
    pub fn pin_slots(&self) -> &[PinSlot] {
        &self.pin_slots
    }

    /// The entry of `pin` of `owner` in the body reached by `call_path` (a linear search:
    /// for tools, resolve once).
    #[must_use]
    pub fn pin_slot(&self, call_path: &[u32], owner: &PinOwner, pin: &str) -> Option<&PinSlot> {
        self.pin_slots
            .iter()
            .find(|p| p.call_path == call_path && &p.owner == owner && p.pin == pin)
    }
}

/// Builds a [`Program`]: allocates slots, places constants, emits instructions and patches
/// jump targets. Used by the compiler; the result is only as valid as what is emitted.
#[derive(Debug)]
pub struct ProgramBuilder {
    program: Program,
    /// Origin given to instructions emitted now.
    current_origin: Option<OriginId>,
    /// Origin → its id, so each is stored once.
    origin_ids: FxHashMap<InstrOrigin, OriginId>,
}

impl ProgramBuilder {
    /// An empty program called `name`.
    #[must_use]
    pub fn new(name: &str) -> Self {
        Self {
            program: Program {
                name: name.to_string(),
                code: Vec::new(),
                operands: Vec::new(),
                construction: 0,
                forward: 0,
                initial: Slots::default(),
                texts: Vec::new(),
                bones: Vec::new(),
                variables: Vec::new(),
                origins: Vec::new(),
                instr_origins: Vec::new(),
                second_origins: Vec::new(),
                pin_slots: Vec::new(),
                scalar_lens: ScalarLens::default(),
                written_lens: ScalarLens::default(),
                kept_lens: ScalarLens::default(),
                id: 0,
                traces: false,
                fingerprint: std::sync::OnceLock::new(),
            },
            current_origin: None,
            origin_ids: FxHashMap::default(),
        }
    }

    fn p(&mut self) -> &mut Program {
        &mut self.program
    }

    /// A new zeroed slot of type `ty`.
    pub fn alloc(&mut self, ty: ValueType) -> u32 {
        self.p().initial.alloc(ty)
    }

    /// A new slot holding the constant `value`. Bone names inside are recorded for
    /// resolution at instantiation with `location`; texts go to the text table.
    pub fn constant(&mut self, value: &Value, location: &str) -> u32 {
        let slot = self.alloc(value.ty());
        self.write(slot, value, location);
        slot
    }

    /// Writes `value` into an existing slot of its type as its initial content.
    pub fn write(&mut self, slot: u32, value: &Value, location: &str) {
        let p = self.p();
        p.initial.write(slot, value);
        match value {
            Value::Bone(Some(name)) => p.bones.push(BoneLiteral {
                name: name.clone(),
                slot: BoneSlot::Scalar(slot),
                location: location.to_string(),
            }),
            Value::Name(text) => {
                p.texts.push(text.clone());
                p.initial.names[slot as usize] = (p.texts.len() - 1) as u32;
            }
            Value::Array(_, items) => {
                for (i, item) in items.iter().enumerate() {
                    if let Value::Bone(Some(name)) = item {
                        p.bones.push(BoneLiteral {
                            name: name.clone(),
                            slot: BoneSlot::ArrayElement {
                                slot,
                                index: i as u32,
                            },
                            location: location.to_string(),
                        });
                    }
                }
            }
            _ => {}
        }
    }

    /// Declares a graph variable living in `slot` (already holding its default).
    pub fn variable(&mut self, info: VariableInfo) -> VariableId {
        let p = self.p();
        p.variables.push(info);
        VariableId((p.variables.len() - 1) as u32)
    }

    /// Position of the next instruction.
    #[must_use]
    pub fn here(&self) -> u32 {
        self.program.code.len() as u32
    }

    /// Emits an instruction with its operands; returns its position.
    pub fn emit(&mut self, op: Op, operands: &[u32]) -> u32 {
        let p = self.p();
        let args = p.operands.len() as u32;
        p.operands.extend_from_slice(operands);
        p.code.push(Instr { op, args });
        let origin = self.current_origin.map_or(NO_ORIGIN, |o| o.0);
        self.program.instr_origins.push(origin);
        (self.program.code.len() - 1) as u32
    }

    /// The id of `origin` in the program's origin table, adding it if new.
    pub fn intern_origin(&mut self, origin: InstrOrigin) -> OriginId {
        if let Some(&id) = self.origin_ids.get(&origin) {
            return id;
        }
        let id = OriginId(self.program.origins.len() as u32);
        self.program.origins.push(origin.clone());
        self.origin_ids.insert(origin, id);
        id
    }

    /// Makes room for `additional` more origins: a caller that knows about how many it will
    /// add saves the table's regrowth (each origin is a few strings).
    pub fn reserve_origins(&mut self, additional: usize) {
        self.program.origins.reserve(additional);
    }

    /// Adds `origin` to the origin table without looking for an equal one: for a caller
    /// that knows no equal origin will be needed again (the compiler adds each node's origin
    /// once per body and event). [`ProgramBuilder::intern_origin`] does not see it.
    pub fn add_origin(&mut self, origin: InstrOrigin) -> OriginId {
        let id = OriginId(self.program.origins.len() as u32);
        self.program.origins.push(origin);
        id
    }

    /// Sets the origin recorded for the instructions emitted from now on (`None`: no
    /// origin); returns the previous one, to restore after a nested node.
    pub fn set_origin(&mut self, origin: Option<OriginId>) -> Option<OriginId> {
        std::mem::replace(&mut self.current_origin, origin)
    }

    /// Records where a pin's value lives (see [`Program::pin_slots`]); never read by the
    /// executor. Returns the entry's index, for [`ProgramBuilder::move_pin_slot`].
    pub fn pin_slot(&mut self, entry: PinSlot) -> usize {
        let pins = &mut self.p().pin_slots;
        pins.push(entry);
        pins.len() - 1
    }

    /// Points pin entry `index` (as returned by [`ProgramBuilder::pin_slot`]) at `slot` of
    /// the same type: the compiler lets a function input or local read another slot that
    /// holds the same value instead of a copy of it.
    pub fn move_pin_slot(&mut self, index: usize, slot: u32) {
        self.p().pin_slots[index].slot = slot;
    }

    /// Sets operand `index` of instruction `at` (used to patch jump targets).
    pub fn patch(&mut self, at: u32, index: usize, value: u32) {
        let p = self.p();
        let args = p.code[at as usize].args as usize;
        p.operands[args + index] = value;
    }

    /// Marks where the construction event starts.
    pub fn set_construction_entry(&mut self, at: u32) {
        self.p().construction = at;
    }

    /// Marks where the forward event starts.
    pub fn set_forward_entry(&mut self, at: u32) {
        self.p().forward = at;
    }

    /// The finished program.
    ///
    /// The executor indexes scalar slots without bounds checks, so this makes sure every
    /// slot operand (by its op's layout, [`Op::operands`]) names an existing slot of its
    /// type, adding zeroed slots if an operand names one past the end (the compiler's
    /// programs never do).
    ///
    /// The executor also fetches instructions without bounds checks, so a program whose
    /// last instruction could fall through past its end (anything but `End` or `Jump`, or
    /// no instruction at all) gets an `End` appended.
    ///
    /// # Panics
    /// If an instruction's op has no operand layout (an op no node compiles to and the
    /// compiler does not emit), a jump target or an event's entry is not an instruction
    /// of the program, or an array operand names an array variable the program does not
    /// have: a program built that way could not be run safely.
    #[must_use]
    pub fn finish(self) -> Program {
        self.finish_with(false)
    }

    /// [`ProgramBuilder::finish`], then packs the scalar slots of values that never
    /// outlive a run into shared slots (see the `sharing` module): a smaller instance, the
    /// same results bit for bit. Only the pin table entries of values that keep a slot of
    /// their own remain ([`Program::pin_slots`]); build with [`ProgramBuilder::finish`]
    /// for tools that show every pin's value.
    ///
    /// # Panics
    /// As [`ProgramBuilder::finish`].
    #[must_use]
    pub fn finish_sharing_slots(self) -> Program {
        self.finish_with(true)
    }

    fn finish_with(mut self, share: bool) -> Program {
        if !matches!(
            self.program.code.last().map(|i| i.op),
            Some(Op::End | Op::Jump)
        ) {
            self.emit(Op::End, &[]);
        }
        // The executor reads every instruction's operands as a window of MAX_OPERANDS.
        let p = &mut self.program;
        p.operands
            .extend(std::iter::repeat_n(0, strider_nodes::MAX_OPERANDS));
        let len = p.code.len();
        for (name, entry) in [("construction", p.construction), ("forward", p.forward)] {
            assert!(
                (entry as usize) < len,
                "the {name} entry {entry} is not one of the {len} instructions"
            );
        }
        let mut layouts = crate::sharing::layouts(p);
        for (pc, (instr, layout)) in p.code.iter().zip(&layouts).enumerate() {
            for (k, &operand) in layout.iter().enumerate() {
                let value = p.operands[instr.args as usize + k];
                match operand {
                    // The batch's array reads and writes find a member's array variable
                    // without a bounds check (`per_member`).
                    Operand::Slot(ValueType::Array(e), _) => assert!(
                        p.initial.has_array(e, value),
                        "instruction {pc} ({:?}) names array variable {value} of {e:?}, which \
                         the program does not have",
                        instr.op
                    ),
                    Operand::Slot(ty, _) => p.initial.cover_slot(ty, value),
                    Operand::Target => assert!(
                        (value as usize) < len,
                        "instruction {pc} ({:?}) jumps to {value}, past the {len} instructions",
                        instr.op
                    ),
                }
            }
        }
        if share {
            crate::sharing::share(p, &mut layouts);
            crate::fusion::fuse(p, &mut layouts);
        }
        p.scalar_lens = ScalarLens::of(&p.initial);
        p.written_lens = written_lens(p, &layouts);
        if !share {
            p.kept_lens = p.written_lens;
        }
        // Numbers from 1 on: 0 is no program.
        static PROGRAMS: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(1);
        p.id = PROGRAMS.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        p.traces = p
            .code
            .iter()
            .any(|i| matches!(i.op, Op::LineTrace | Op::SphereTrace));
        self.program
    }
}

/// One past the highest slot of each scalar type that an instruction of `p` (operand
/// layouts `layouts`) writes.
fn written_lens(p: &Program, layouts: &Layouts) -> ScalarLens {
    debug_assert_eq!(layouts.len(), p.code.len(), "a layout per instruction");
    let mut lens = ScalarLens::default();
    for (instr, layout) in p.code.iter().zip(layouts) {
        for (k, &operand) in layout.iter().enumerate() {
            if let Operand::Slot(ty, access) = operand
                && access != strider_nodes::Access::Read
                && let Some(t) = crate::slots::scalar(ty)
            {
                let slot = p.operands[instr.args as usize + k] as usize;
                lens.0[t] = lens.0[t].max(slot + 1);
            }
        }
    }
    lens
}
