//! Slot sharing: values that live only within one run of an event share scalar slots.
//!
//! The compiler gives every node output, function input, local and loop variable of every
//! call site a slot of its own, so tools can show each pin's value after a frame. Most of
//! those values are written and last read within a few instructions of each other, and an
//! instance carrying a slot for each of them is several times larger than the values alive
//! at any one point: for a crowd, the instance's memory no longer fits the caches, and
//! each frame waits on it.
//!
//! [`share`] finds, by liveness over the program's control flow, the scalar slots (bools,
//! ints, floats, vectors, rotations, transforms) whose value never outlives a run, and
//! packs those whose live ranges do not overlap into the same slot:
//!
//! - A slot is *kept* (never shared) when its value may be read before it is written in a
//!   run of either event (live at an event's entry: constants, node state, variables read
//!   before they are set, anything the construction leaves for the frames or a frame for
//!   the next), or when it holds a graph variable (the host reads and sets those between
//!   runs).
//! - Every other slot is live over a set of instructions; its *range* is the span of
//!   program positions from the first to the last of them, including every instruction
//!   that reads or writes it. Two such slots of one type whose ranges do not overlap are
//!   never live at the same point, and take the same slot (greedy interval partitioning,
//!   which uses the fewest slots for a set of ranges).
//!
//! Copies mostly go too (coalescing, as a register allocator does), wherever one slot can
//! hold both the copy's source and its destination:
//!
//! - a value whose range ends at the copy into one whose range starts there (a result out
//!   of a function, a node's value into a call's input), or two values each written once,
//!   the second by the copy: the two take one slot;
//! - a constant into a slot written only by the copy, or a kept slot (a graph variable,
//!   say) into one read only later in the copy's straight run of instructions while the
//!   kept slot is not written: readers read the constant or the kept slot where it is;
//! - a value (with what was merged into it) whose whole range lies in the copy's straight
//!   run and starts with a write, into a kept slot: its writers write the kept slot
//!   instead, if nothing touches the kept slot from that write up to the copy (so its
//!   first writer does not read it) and nothing writes either while the value is still
//!   read after the copy.
//!
//! The copy then reads and writes one slot, and is removed from the program.
//!
//! It relies on what [`Access`] documents: an instruction writes each of its written
//! operands whenever it runs (and, for a loop step, whenever it does not jump), so a write
//! ends whatever value the slot held before.
//!
//! Written here because no crate does liveness over this instruction set; the bit sets
//! are `fixedbitset`'s.

use crate::program::{Instr, PinSlot, Program};
use crate::slots::{SCALAR_TYPES, ScalarLens, Slots, scalar};
use fixedbitset::FixedBitSet;
use std::borrow::Cow;
use std::cmp::Reverse;
use std::collections::BinaryHeap;
use strider_nodes::{Access, Op, Operand, ValueType};

/// Every scalar slot of the program numbered in one range: type `t`'s slot `s` is
/// `base[t] + s`.
struct Ids {
    base: [usize; 7],
}

impl Ids {
    fn new(lens: [usize; 6]) -> Self {
        let mut base = [0; 7];
        for t in 0..6 {
            base[t + 1] = base[t] + lens[t];
        }
        Self { base }
    }

    fn count(&self) -> usize {
        self.base[6]
    }

    fn id(&self, ty: ValueType, slot: u32) -> Option<usize> {
        scalar(ty).map(|t| self.base[t] + slot as usize)
    }
}

/// Each instruction's scalar slot reads and writes, as ids, in two flat lists.
struct Accesses {
    uses: Vec<u32>,
    defs: Vec<u32>,
    /// Instruction `pc`'s reads are `uses[use_at[pc]..use_at[pc + 1]]`; likewise `def_at`.
    use_at: Vec<usize>,
    def_at: Vec<usize>,
}

impl Accesses {
    fn of(program: &Program, layouts: &[Cow<'static, [Operand]>], ids: &Ids) -> Self {
        let mut a = Accesses {
            uses: Vec::new(),
            defs: Vec::new(),
            use_at: vec![0],
            def_at: vec![0],
        };
        for (instr, layout) in program.code.iter().zip(layouts) {
            for (k, operand) in layout.iter().enumerate() {
                let Operand::Slot(ty, access) = *operand else {
                    continue;
                };
                let Some(id) = ids.id(ty, program.operands[instr.args as usize + k]) else {
                    continue;
                };
                if access != Access::Write {
                    a.uses.push(id as u32);
                }
                if access != Access::Read {
                    a.defs.push(id as u32);
                }
            }
            a.use_at.push(a.uses.len());
            a.def_at.push(a.defs.len());
        }
        a
    }

    /// Drops the reads of slots not in `slots`.
    fn only_uses_of(&mut self, slots: &FixedBitSet) {
        let mut uses = Vec::with_capacity(self.uses.len());
        for pc in 0..self.use_at.len() - 1 {
            let start = uses.len();
            uses.extend(
                self.uses[self.use_at[pc]..self.use_at[pc + 1]]
                    .iter()
                    .filter(|&&u| slots.contains(u as usize)),
            );
            self.use_at[pc] = start;
        }
        *self.use_at.last_mut().expect("one past the last") = uses.len();
        self.uses = uses;
    }

    fn uses(&self, pc: usize) -> &[u32] {
        &self.uses[self.use_at[pc]..self.use_at[pc + 1]]
    }

    fn defs(&self, pc: usize) -> &[u32] {
        &self.defs[self.def_at[pc]..self.def_at[pc + 1]]
    }
}

/// Where control goes after instruction `instr` (laid out as `layout`) at `pc`: the next
/// instruction unless the op ends the event or always jumps, and its jump target if any.
fn successors(
    program: &Program,
    instr: &Instr,
    layout: &[Operand],
    pc: usize,
) -> [Option<usize>; 2] {
    let target = layout
        .iter()
        .position(|o| *o == Operand::Target)
        .map(|k| program.operands[instr.args as usize + k] as usize);
    let falls_through = !matches!(instr.op, Op::End | Op::Jump);
    [falls_through.then_some(pc + 1), target]
}

/// Each instruction's operand layout ([`Op::operands`]), in program order: worked out once
/// when a program is finished, and kept in step as sharing and fusion remove instructions.
pub(crate) type Layouts = Vec<Cow<'static, [Operand]>>;

/// The operand layouts of `program`'s instructions.
///
/// # Panics
/// If an instruction's op has no layout (no node compiles to it).
pub(crate) fn layouts(program: &Program) -> Layouts {
    program
        .code
        .iter()
        .map(|instr| {
            instr
                .op
                .operands()
                .unwrap_or_else(|| panic!("{:?} has no operand layout", instr.op))
        })
        .collect()
}

/// The first instruction of every basic block (and one past the last): the entries, the
/// jump targets and whatever follows an instruction that does not simply fall through.
/// `layouts` are the instructions' operand layouts.
pub(crate) fn leaders(program: &Program, layouts: &[Cow<'static, [Operand]>]) -> FixedBitSet {
    let mut leader = FixedBitSet::with_capacity(program.code.len() + 1);
    leader.insert(program.construction as usize);
    leader.insert(program.forward as usize);
    for (pc, (instr, layout)) in program.code.iter().zip(layouts).enumerate() {
        let [next, target] = successors(program, instr, layout, pc);
        if let Some(t) = target {
            leader.insert(t);
        }
        if target.is_some() || next.is_none() {
            leader.insert(pc + 1);
        }
    }
    leader
}

/// A run of instructions entered only at its first and left only after its last.
struct Block {
    start: usize,
    /// One past the last instruction.
    end: usize,
    /// Read before written in the block (up to its terminator, if it branches).
    gen_: FixedBitSet,
    /// Written in the block (up to its terminator).
    kill: FixedBitSet,
    /// Whether the last instruction jumps or ends the event (and is left out of
    /// `gen_`/`kill`: its writes happen only when it falls through).
    branches: bool,
    live_in: FixedBitSet,
}

/// Shares the program's scalar slots as the [module docs](self) describe; rewrites the
/// operands, the initial memory image, the variables' slots and the pin table (which keeps
/// only the values that still own their slot), and removes the copies that coalescing
/// leaves reading and writing one slot, with their entries of `layouts` (the
/// instructions' operand layouts, [`Op::operands`]). The program's operands must all name
/// existing slots.
pub(crate) fn share(program: &mut Program, layouts: &mut Layouts) {
    debug_assert_eq!(
        layouts.len(),
        program.code.len(),
        "a layout per instruction"
    );
    let ids = Ids::new(ScalarLens::of(&program.initial).0);
    let n_ids = ids.count();
    let n = program.code.len();
    let mut acc = Accesses::of(program, layouts, &ids);
    // Slots no instruction writes (constants, mostly) keep their first value in every run:
    // kept if read, and left out of the liveness, where they would be live everywhere.
    let mut written = FixedBitSet::with_capacity(n_ids);
    written.extend(acc.defs.iter().map(|&d| d as usize));
    let mut kept = FixedBitSet::with_capacity(n_ids);
    kept.extend(
        acc.uses
            .iter()
            .map(|&u| u as usize)
            .filter(|&u| !written.contains(u)),
    );
    acc.only_uses_of(&written);

    let leader = leaders(program, layouts);
    let mut block_of = vec![0u32; n];
    let mut blocks: Vec<Block> = Vec::new();
    let mut start = 0;
    while start < n {
        let mut end = start + 1;
        while end < n && !leader.contains(end) {
            end += 1;
        }
        let last = end - 1;
        let [next, target] = successors(program, &program.code[last], &layouts[last], last);
        let branches = target.is_some() || next.is_none();
        let body_end = if branches { last } else { end };
        let (mut gen_, mut kill) = (
            FixedBitSet::with_capacity(n_ids),
            FixedBitSet::with_capacity(n_ids),
        );
        for pc in (start..body_end).rev() {
            for &d in acc.defs(pc) {
                gen_.set(d as usize, false);
                kill.insert(d as usize);
            }
            for &u in acc.uses(pc) {
                gen_.insert(u as usize);
            }
        }
        block_of[start..end].fill(blocks.len() as u32);
        blocks.push(Block {
            start,
            end,
            gen_,
            kill,
            branches,
            live_in: FixedBitSet::with_capacity(n_ids),
        });
        start = end;
    }

    // Live after the block's body: at its terminator (a branch reads its operands, writes
    // only when falling through), or at the next block.
    let live_out = |blocks: &[Block], b: usize, out: &mut FixedBitSet| {
        out.clear();
        let block = &blocks[b];
        let last = block.end - 1;
        let [next, target] = successors(program, &program.code[last], &layouts[last], last);
        let next = if block.branches {
            next
        } else {
            Some(block.end)
        };
        if let Some(next) = next.filter(|&p| p < n) {
            out.union_with(&blocks[block_of[next] as usize].live_in);
        }
        if block.branches {
            for &d in acc.defs(last) {
                out.set(d as usize, false);
            }
            for &u in acc.uses(last) {
                out.insert(u as usize);
            }
        }
        if let Some(t) = target {
            out.union_with(&blocks[block_of[t] as usize].live_in);
        }
    };
    let mut out = FixedBitSet::with_capacity(n_ids);
    let mut changed = true;
    while changed {
        changed = false;
        for b in (0..blocks.len()).rev() {
            live_out(&blocks, b, &mut out);
            out.difference_with(&blocks[b].kill);
            out.union_with(&blocks[b].gen_);
            if out != blocks[b].live_in {
                std::mem::swap(&mut blocks[b].live_in, &mut out);
                changed = true;
            }
        }
    }

    // Kept: also live at an event's entry, or a variable.
    for entry in [program.construction, program.forward] {
        kept.union_with(&blocks[block_of[entry as usize] as usize].live_in);
    }
    for v in &program.variables {
        if let Some(id) = ids.id(v.ty, v.slot) {
            kept.insert(id);
        }
    }

    // Ranges: the first and last position where each slot is live, read or written.
    let mut lo = vec![usize::MAX; n_ids];
    let mut hi = vec![0usize; n_ids];
    let mut extend = |id: usize, pc: usize| {
        lo[id] = lo[id].min(pc);
        hi[id] = hi[id].max(pc);
    };
    for pc in 0..n {
        for &id in acc.uses(pc).iter().chain(acc.defs(pc)) {
            extend(id as usize, pc);
        }
    }
    for b in 0..blocks.len() {
        for id in blocks[b].live_in.ones() {
            extend(id, blocks[b].start);
        }
        live_out(&blocks, b, &mut out);
        for id in out.ones() {
            extend(id, blocks[b].end - 1);
        }
    }

    let (group, dropped) = coalesce_copies(
        program,
        &acc,
        &ids,
        Liveness {
            kept: &kept,
            written: &written,
            lo: &mut lo,
            hi: &mut hi,
            block_of: &block_of,
        },
    );

    // Whether some instruction writes each slot once copies are coalesced: a slot written
    // itself, or one a written slot was merged into.
    let mut written_after = written.clone();
    for id in written.ones() {
        written_after.insert(group[id] as usize);
    }

    // New slots, per type: the kept ones that instructions write first, in their old
    // order (a batch copies them into its lanes and back), then the shared ones by greedy
    // interval partitioning (a batch copies them neither way), then the kept ones no
    // instruction writes (constants, variables only the host sets: a batch copies them
    // into its lanes but never back); a slot coalesced into another takes that one's.
    let mut map = vec![u32::MAX; n_ids];
    let mut occupants: Vec<Vec<u32>> = Vec::with_capacity(6);
    let mut after = [0; 6];
    for (t, slots) in after.iter_mut().enumerate() {
        let range = ids.base[t]..ids.base[t + 1];
        // Per new slot, how many old slots it holds; a new slot is the next index.
        let mut held: Vec<u32> = Vec::new();
        let new_slot = |held: &mut Vec<u32>| {
            held.push(1);
            held.len() as u32 - 1
        };
        for id in range
            .clone()
            .filter(|&id| kept.contains(id) && written_after.contains(id))
        {
            map[id] = new_slot(&mut held);
        }
        // The kept, written slots are the first ones: a batch copies them in and back.
        program.kept_lens.0[t] = held.len();
        let mut shared: Vec<usize> = range
            .clone()
            .filter(|&id| !kept.contains(id) && group[id] == id as u32 && lo[id] != usize::MAX)
            .collect();
        shared.sort_by_key(|&id| (lo[id], id));
        // (end of range, slot) of the slots in use, earliest end on top.
        let mut busy: BinaryHeap<Reverse<(usize, u32)>> = BinaryHeap::new();
        for id in shared {
            let slot = match busy.peek() {
                Some(&Reverse((end, slot))) if end < lo[id] => {
                    busy.pop();
                    held[slot as usize] += 1;
                    slot
                }
                _ => new_slot(&mut held),
            };
            map[id] = slot;
            busy.push(Reverse((hi[id], slot)));
        }
        for id in range
            .clone()
            .filter(|&id| kept.contains(id) && !written_after.contains(id))
        {
            map[id] = new_slot(&mut held);
        }
        for id in range.filter(|&id| group[id] != id as u32) {
            map[id] = map[group[id] as usize];
            if map[id] != u32::MAX {
                held[map[id] as usize] += 1;
            }
        }
        *slots = held.len();
        occupants.push(held);
    }

    // Rewrite.
    for (instr, layout) in program.code.iter().zip(layouts.iter()) {
        for (k, operand) in layout.iter().enumerate() {
            if let Operand::Slot(ty, _) = *operand
                && let Some(id) = ids.id(ty, program.operands[instr.args as usize + k])
            {
                program.operands[instr.args as usize + k] = map[id];
            }
        }
    }
    for v in &mut program.variables {
        if let Some(id) = ids.id(v.ty, v.slot) {
            v.slot = map[id];
        }
    }
    let owns = |p: &PinSlot| match ids.id(p.ty, p.slot) {
        None => true,
        Some(id) => {
            let t = scalar(p.ty).unwrap_or_default();
            map[id] != u32::MAX && occupants[t][map[id] as usize] == 1
        }
    };
    program.pin_slots.retain(owns);
    for p in &mut program.pin_slots {
        if let Some(id) = ids.id(p.ty, p.slot) {
            p.slot = map[id];
        }
    }
    remove_instructions(program, layouts, &dropped);
    let old = &program.initial;
    let mut initial = Slots {
        bones: old.bones.clone(),
        names: old.names.clone(),
        bool_arrays: old.bool_arrays.clone(),
        int_arrays: old.int_arrays.clone(),
        float_arrays: old.float_arrays.clone(),
        vec3_arrays: old.vec3_arrays.clone(),
        quat_arrays: old.quat_arrays.clone(),
        transform_arrays: old.transform_arrays.clone(),
        bone_arrays: old.bone_arrays.clone(),
        ..Slots::default()
    };
    for (t, &ty) in SCALAR_TYPES.iter().enumerate() {
        for _ in 0..after[t] {
            initial.alloc(ty);
        }
    }
    // A kept slot keeps its first value; a shared slot's first value is never read.
    let kept_of = |t: usize| {
        (ids.base[t]..ids.base[t + 1])
            .filter(|&id| kept.contains(id))
            .map(|id| (id - ids.base[t], map[id] as usize))
            .collect::<Vec<_>>()
    };
    carry(&old.bools, &mut initial.bools, &kept_of(0));
    carry(&old.ints, &mut initial.ints, &kept_of(1));
    carry(&old.floats, &mut initial.floats, &kept_of(2));
    carry(&old.vec3s, &mut initial.vec3s, &kept_of(3));
    carry(&old.quats, &mut initial.quats, &kept_of(4));
    carry(&old.transforms, &mut initial.transforms, &kept_of(5));
    program.initial = initial;
}

/// Copies `old[from]` to `new[to]` for each `(from, to)` of `moves`.
fn carry<T: Copy>(old: &[T], new: &mut [T], moves: &[(usize, usize)]) {
    for &(from, to) in moves {
        new[to] = old[from];
    }
}

/// What the copy coalescing reads of the liveness: the kept slots, the slots written at
/// all, each slot's range (first and last position, widened as slots merge) and each
/// instruction's block.
struct Liveness<'a> {
    kept: &'a FixedBitSet,
    written: &'a FixedBitSet,
    lo: &'a mut [usize],
    hi: &'a mut [usize],
    block_of: &'a [u32],
}

/// Finds the copies that can go (see the [module docs](self)) and merges their slots:
/// returns each slot's group (the slot whose new slot it takes; itself if none; a kept
/// slot is always its own) and the copies to remove. Groups stay flat: a merge points the
/// merged slot, and any slots already merged into it, straight at the new group's slot.
fn coalesce_copies(
    program: &Program,
    acc: &Accesses,
    ids: &Ids,
    live: Liveness<'_>,
) -> (Vec<u32>, FixedBitSet) {
    let Liveness {
        kept,
        written,
        lo,
        hi,
        block_of,
    } = live;
    let n_ids = ids.count();
    let mut group: Vec<u32> = (0..n_ids as u32).collect();
    let mut has_members = FixedBitSet::with_capacity(n_ids);
    let mut dropped = FixedBitSet::with_capacity(program.code.len());
    let mut defs = vec![0u32; n_ids];
    for &d in &acc.defs {
        defs[d as usize] += 1;
    }
    for (pc, instr) in program.code.iter().enumerate() {
        let Op::Copy(ty) = instr.op else {
            continue;
        };
        let at = instr.args as usize;
        let (Some(s), Some(d)) = (
            ids.id(ty, program.operands[at]),
            ids.id(ty, program.operands[at + 1]),
        ) else {
            continue;
        };
        let (gs, gd) = (group[s] as usize, group[d] as usize);
        // Whether `slots` name `root` or a slot merged into it (which now shares its slot).
        let names =
            |slots: &[u32], root: usize| slots.iter().any(|&x| group[x as usize] as usize == root);
        // In no group, and with nothing merged into it.
        let alone = |id: usize| group[id] == id as u32 && !has_members.contains(id);
        // Alone, and written by one instruction only.
        let single = |id: usize| alone(id) && defs[id] == 1;
        // Positions `from` to `to` lie in the copy's block (a straight run of instructions).
        let straight = |from: usize, to: usize| {
            from <= to
                && to < block_of.len()
                && block_of[from] == block_of[pc]
                && block_of[to] == block_of[pc]
        };
        // A slot's range ends at the copy only if no later instruction reads it, unless the
        // copy ends its block (where the range ends for anything live after the block).
        let dies_here = |id: usize| hi[id] == pc && straight(pc, pc + 1);
        // `id`'s first position is its one write, before the copy.
        let written_first = |id: usize| {
            lo[id] < pc
                && acc
                    .defs(lo[id])
                    .iter()
                    .filter(|&&x| x as usize == id)
                    .count()
                    == 1
        };
        if gs == gd {
            // Merged already: the copy reads and writes one slot.
            dropped.insert(pc);
            continue;
        }
        // (slot to merge, group it joins)
        let merge = if kept.contains(gs) && !written.contains(gs) {
            // From a constant into a slot only this copy writes: its readers read the
            // constant.
            (!kept.contains(d) && single(d)).then_some((d, gs))
        } else if !kept.contains(gs) && !kept.contains(gd) {
            // From a slot that dies here into one born here; or between two slots written
            // once each, the second born here (both hold one value from the copy on).
            let born_here = lo[gd] == pc && alone(gd);
            (born_here && (dies_here(gs) || (single(s) && single(d) && written_first(s))))
                .then_some((gd, gs))
        } else if kept.contains(gs) {
            // From a kept slot into a slot only this copy writes, read only later in the
            // copy's straight run while the kept slot is not written.
            let last = hi[d];
            (!kept.contains(d)
                && single(d)
                && lo[d] == pc
                && last > pc
                && straight(pc, last + 1)
                && (pc + 1..=last).all(|q| !names(acc.defs(q), gs)))
            .then_some((d, gs))
        } else {
            // Into a kept slot, from a slot (with what was merged into it) whose whole range
            // lies in the copy's straight run and starts with a write: its writers write the
            // kept slot instead, if nothing else touches the kept slot from the first write
            // on, and nothing writes either after the copy while the value is still read
            // (the kept slot must keep the copied value).
            let (p, last) = (lo[gs], hi[gs]);
            (p < pc
                && straight(p, pc)
                && names(acc.defs(p), gs)
                && !names(acc.uses(p), gs)
                && (p..pc).all(|q| !names(acc.uses(q), gd) && !names(acc.defs(q), gd))
                && (dies_here(gs)
                    || (last > pc
                        && straight(pc, last + 1)
                        && (pc + 1..=last)
                            .all(|q| !names(acc.defs(q), gd) && !names(acc.defs(q), gs)))))
            .then_some((gs, gd))
        };
        if let Some((member, root)) = merge {
            if has_members.contains(member) {
                for g in group.iter_mut().filter(|g| **g as usize == member) {
                    *g = root as u32;
                }
            }
            group[member] = root as u32;
            has_members.insert(root);
            if !kept.contains(root) {
                lo[root] = lo[root].min(lo[member]);
                hi[root] = hi[root].max(hi[member]);
            }
            dropped.insert(pc);
        }
    }
    (group, dropped)
}

/// Removes the instructions in `dropped` (here, copies that now read and write one slot;
/// the second halves of fused pairs in `fusion`), and their `layouts` (the instructions'
/// operand layouts): a jump or an entry to one goes to the instruction after it.
pub(crate) fn remove_instructions(
    program: &mut Program,
    layouts: &mut Layouts,
    dropped: &FixedBitSet,
) {
    if dropped.is_clear() {
        return;
    }
    let n = program.code.len();
    let mut new_pc = Vec::with_capacity(n + 1);
    let mut next = 0u32;
    for pc in 0..n {
        new_pc.push(next);
        if !dropped.contains(pc) {
            next += 1;
        }
    }
    new_pc.push(next);
    for (pc, (instr, layout)) in program.code.iter().zip(layouts.iter()).enumerate() {
        if dropped.contains(pc) {
            continue;
        }
        for (k, operand) in layout.iter().enumerate() {
            if *operand == Operand::Target {
                let target = &mut program.operands[instr.args as usize + k];
                *target = new_pc[*target as usize];
            }
        }
    }
    program.construction = new_pc[program.construction as usize];
    program.forward = new_pc[program.forward as usize];
    let keep = |pc: &mut usize| {
        let kept = !dropped.contains(*pc);
        *pc += 1;
        kept
    };
    let mut pc = 0;
    program.code.retain(|_| keep(&mut pc));
    let mut pc = 0;
    layouts.retain(|_| keep(&mut pc));
    let mut pc = 0;
    program.instr_origins.retain(|_| keep(&mut pc));
    if !program.second_origins.is_empty() {
        let mut pc = 0;
        program.second_origins.retain(|_| keep(&mut pc));
    }
}

#[cfg(test)]
mod tests {
    use crate::ProgramBuilder;
    use strider_nodes::{Op, Value, ValueType};

    /// The slots no instruction writes come after every written one, and the written ones
    /// that outlive a run before the temporaries, so a batch copies in only `0..kept_lens`
    /// and `written_lens..` and back only `0..kept_lens`: here two constants and a state
    /// carried from frame to frame among three temporaries.
    #[test]
    fn slots_no_instruction_writes_come_last() {
        let mut pb = ProgramBuilder::new("order");
        let two = pb.constant(&Value::Float(2.0), "");
        let three = pb.constant(&Value::Float(3.0), "");
        let state = pb.alloc(ValueType::Float);
        let (a, b, c) = (
            pb.alloc(ValueType::Float),
            pb.alloc(ValueType::Float),
            pb.alloc(ValueType::Float),
        );
        pb.set_construction_entry(pb.here());
        pb.emit(Op::End, &[]);
        pb.set_forward_entry(pb.here());
        pb.emit(Op::AddF, &[two, three, a]);
        pb.emit(Op::MulF, &[a, state, b]);
        pb.emit(Op::AddF, &[b, two, c]);
        pb.emit(Op::AddF, &[c, state, state]);
        pb.emit(Op::End, &[]);
        let program = pb.finish_sharing_slots();
        let float = 2;
        let (all, written) = (program.scalar_lens.0[float], program.written_lens.0[float]);
        assert_eq!(
            all - written,
            2,
            "the two constants, after everything written"
        );
        for (instr, layout) in program.code.iter().map(|i| (i, i.op.operands().unwrap())) {
            for (k, operand) in layout.iter().enumerate() {
                let slot = program.operands[instr.args as usize + k] as usize;
                match operand {
                    strider_nodes::Operand::Slot(ValueType::Float, strider_nodes::Access::Read) => {
                        assert!(slot < all)
                    }
                    strider_nodes::Operand::Slot(ValueType::Float, _) => assert!(slot < written),
                    _ => {}
                }
            }
        }
        let values = &program.initial.floats[written..];
        assert!(values.contains(&2.0) && values.contains(&3.0));
        // The state first, then the temporaries: walking the straight code operand by
        // operand, the state is read before it is written; the temporaries are written
        // first.
        let kept = program.kept_lens.0[float];
        assert_eq!(kept, 1, "the state alone outlives a run");
        let mut first_read = vec![None; written];
        for (instr, layout) in program.code.iter().map(|i| (i, i.op.operands().unwrap())) {
            for (k, operand) in layout.iter().enumerate() {
                let slot = program.operands[instr.args as usize + k] as usize;
                if let strider_nodes::Operand::Slot(ValueType::Float, access) = operand
                    && slot < written
                    && first_read[slot].is_none()
                {
                    first_read[slot] = Some(*access == strider_nodes::Access::Read);
                }
            }
        }
        assert_eq!(first_read[..kept], [Some(true)], "{:?}", program.operands);
        assert!(first_read[kept..].iter().all(|&r| r == Some(false)));
    }
}
