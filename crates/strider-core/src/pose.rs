//! [`Pose`]: a skeleton's current local and global transforms.
//!
//! Locals are the source of truth. Globals are cached and recomputed lazily: changing a
//! local marks the bone's subtree stale (a contiguous range, thanks to the skeleton's
//! depth-first order), and reading a global recomputes only the stale chain above it.
//! The stale flags are a bit set: marking a subtree is a few word operations.
//! Nothing here allocates after [`Pose::new`].

use crate::skeleton::{BoneIndex, Skeleton};
use crate::transform::Transform;
use std::sync::Arc;

/// The current pose of one character: local and global transform per bone.
#[derive(Clone, Debug)]
pub struct Pose {
    skeleton: Arc<Skeleton>,
    locals: Vec<Transform>,
    globals: Vec<Transform>,
    /// Bit `i % 64` of word `i / 64`: bone `i`'s global is stale.
    stale: Vec<u64>,
}

impl Pose {
    /// Bytes of heap memory the pose holds (its local and global transforms and their
    /// flags; the skeleton is shared and not counted).
    #[must_use]
    pub fn heap_bytes(&self) -> usize {
        (self.locals.capacity() + self.globals.capacity()) * std::mem::size_of::<Transform>()
            + self.stale.capacity() * std::mem::size_of::<u64>()
    }

    /// The rest pose of `skeleton`.
    #[must_use]
    pub fn new(skeleton: Arc<Skeleton>) -> Self {
        let locals = skeleton.rest_locals().to_vec();
        let globals = skeleton.rest_globals().to_vec();
        let stale = vec![0; locals.len().div_ceil(64)];
        Self {
            skeleton,
            locals,
            globals,
            stale,
        }
    }

    /// The skeleton this pose belongs to.
    #[must_use]
    pub fn skeleton(&self) -> &Arc<Skeleton> {
        &self.skeleton
    }

    /// Number of bones.
    #[must_use]
    pub fn len(&self) -> usize {
        self.locals.len()
    }

    /// Always false: a skeleton has at least one bone.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.locals.is_empty()
    }

    /// Resets every bone to the rest pose.
    pub fn reset_to_rest(&mut self) {
        self.locals.copy_from_slice(self.skeleton.rest_locals());
        self.globals.copy_from_slice(self.skeleton.rest_globals());
        self.stale.fill(0);
    }

    /// Replaces all locals (storage order, as [`Skeleton::names`]). Extra entries are
    /// ignored; missing ones keep their current value.
    pub fn set_locals(&mut self, locals: &[Transform]) {
        let n = self.locals.len().min(locals.len());
        self.locals[..n].copy_from_slice(&locals[..n]);
        self.mark_stale(0, self.locals.len());
    }

    /// A bone's transform relative to its parent.
    #[must_use]
    pub fn local(&self, bone: BoneIndex) -> Transform {
        self.locals[bone.get()]
    }

    /// All local transforms in storage order.
    #[must_use]
    pub fn locals(&self) -> &[Transform] {
        &self.locals
    }

    /// Sets a bone's local transform. Descendants follow (their locals are unchanged).
    pub fn set_local(&mut self, bone: BoneIndex, local: Transform) {
        let i = bone.get();
        self.locals[i] = local;
        let end = self.skeleton.subtree_end(bone);
        self.mark_stale(i, end);
    }

    /// Whether bone `i`'s global is stale.
    #[inline]
    fn is_stale(&self, i: usize) -> bool {
        self.stale[i / 64] & (1 << (i % 64)) != 0
    }

    /// Marks bone `i`'s global current.
    #[inline]
    fn mark_current(&mut self, i: usize) {
        self.stale[i / 64] &= !(1 << (i % 64));
    }

    /// Marks the globals of bones `from..to` stale.
    #[inline]
    fn mark_stale(&mut self, from: usize, to: usize) {
        let bit = from % 64;
        if from < to && to - from <= 64 - bit {
            // Within one word: a bone's subtree, on most skeletons.
            self.stale[from / 64] |= (u64::MAX >> (64 - (to - from))) << bit;
            return;
        }
        let mut i = from;
        while i < to {
            let bit = i % 64;
            let n = (to - i).min(64 - bit);
            self.stale[i / 64] |= (u64::MAX >> (64 - n)) << bit;
            i += n;
        }
    }

    /// A bone's rig-space transform, recomputing stale ancestors first.
    #[inline]
    pub fn global(&mut self, bone: BoneIndex) -> Transform {
        let i = bone.get();
        if self.is_stale(i) {
            self.refresh(bone);
        }
        self.globals[i]
    }

    /// Recomputes the stale global of `bone` and of its stale ancestors.
    #[cold]
    fn refresh(&mut self, bone: BoneIndex) {
        let i = bone.get();
        let g = match self.skeleton.parent(bone) {
            Some(p) => self.global(p) * self.locals[i],
            None => self.locals[i],
        };
        self.globals[i] = g;
        self.mark_current(i);
    }

    /// Sets a bone's rig-space transform.
    ///
    /// With `propagate_to_children` the children keep their local transforms and so move
    /// with the bone (RigVM's "Propagate to Children"). Without it the children keep their
    /// global transforms: their locals are recomputed against the new parent.
    pub fn set_global(&mut self, bone: BoneIndex, global: Transform, propagate_to_children: bool) {
        // Read as the caller stored it a moment ago.
        let global = global.load_stored();
        if !propagate_to_children {
            for k in 0..self.skeleton.children(bone).len() {
                let c = self.skeleton.children(bone)[k];
                let _ = self.global(c);
            }
        }
        let i = bone.get();
        let local = match self.skeleton.parent(bone) {
            Some(p) => global.relative_to(&self.global(p)),
            None => global,
        };
        self.locals[i] = local;
        self.globals[i] = global;
        self.mark_current(i);
        if propagate_to_children {
            let end = self.skeleton.subtree_end(bone);
            self.mark_stale(i + 1, end);
        } else {
            for &c in self.skeleton.children(bone) {
                let ci = c.get();
                self.locals[ci] = self.globals[ci].relative_to(&global);
            }
        }
    }

    /// Sets the rig-space transforms of a chain `[a, b, c]`, each with
    /// `propagate_to_children` (as [`Pose::set_global`] on `a`, then `b`, then `c`: bones
    /// below them keep their locals and follow). When `b` is `a`'s child and `c` is `b`'s,
    /// as in a limb, the locals are computed along the chain in one pass and `a`'s subtree
    /// is marked stale once; otherwise it is the three calls.
    pub fn set_chain_globals(&mut self, bones: [BoneIndex; 3], globals: [Transform; 3]) {
        if !self.is_limb(bones) {
            for (bone, global) in bones.into_iter().zip(globals) {
                self.set_global(bone, global, true);
            }
            return;
        }
        let [ga, gb, gc] = globals.map(|g| g.load_stored());
        let la = match self.skeleton.parent(bones[0]) {
            Some(p) => ga.relative_to(&self.global(p)),
            None => ga,
        };
        let locals = [la, gb.relative_to(&ga), gc.relative_to(&gb)];
        self.store_limb(bones, [ga, gb, gc], locals);
    }

    /// [`Pose::set_chain_globals`] of a limb (`b` is `a`'s child and `c` is `b`'s) whose
    /// new locals the caller has computed as that method does: `locals[0]` is `a`'s new
    /// global relative to its parent's current one ([`Transform::relative_to`]; the
    /// global itself for a bone without a parent), `locals[1]` `b`'s relative to `a`'s new
    /// global, `locals[2]` `c`'s relative to `b`'s. For solvers that compute many chains
    /// at once (the batched two-bone IK). Returns false, changing nothing, when the bones
    /// are not such a limb.
    #[inline]
    pub fn set_chain_with_locals(
        &mut self,
        bones: [BoneIndex; 3],
        globals: [Transform; 3],
        locals: [Transform; 3],
    ) -> bool {
        let limb = self.is_limb(bones);
        if limb {
            self.store_limb(bones, globals, locals);
        }
        limb
    }

    /// Whether `b` is `a`'s child and `c` is `b`'s.
    fn is_limb(&self, [a, b, c]: [BoneIndex; 3]) -> bool {
        self.skeleton.parent(b) == Some(a) && self.skeleton.parent(c) == Some(b)
    }

    /// Stores a limb's new globals and locals: its bones' globals are current, the rest of
    /// `a`'s subtree stale.
    #[inline]
    fn store_limb(
        &mut self,
        [a, b, c]: [BoneIndex; 3],
        globals: [Transform; 3],
        locals: [Transform; 3],
    ) {
        let end = self.skeleton.subtree_end(a);
        let (ia, ib, ic) = (a.get(), b.get(), c.get());
        [self.locals[ia], self.locals[ib], self.locals[ic]] = locals;
        [self.globals[ia], self.globals[ib], self.globals[ic]] = globals;
        // `b` and `c` lie in `a`'s subtree (depth-first order): everything below `a`
        // follows, but for the two bones set here.
        self.mark_current(ia);
        self.mark_stale(ia + 1, end);
        self.mark_current(ib);
        self.mark_current(ic);
    }

    /// Brings every global up to date and returns them all (storage order).
    pub fn globals(&mut self) -> &[Transform] {
        for i in 0..self.globals.len() {
            if self.is_stale(i) {
                let bone = BoneIndex(i as u32);
                self.globals[i] = match self.skeleton.parent(bone) {
                    // Parents come first in storage order, so theirs is already fresh.
                    Some(p) => self.globals[p.get()] * self.locals[i],
                    None => self.locals[i],
                };
                self.mark_current(i);
            }
        }
        &self.globals
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::skeleton::Bone;
    use glam::{Quat, Vec3};

    fn chain() -> Arc<Skeleton> {
        let b = |name: &str, parent: Option<&str>, t: Vec3| Bone {
            name: name.into(),
            parent: parent.map(Into::into),
            rest_local: Transform::from_translation(t),
        };
        Arc::new(
            Skeleton::new(vec![
                b("root", None, Vec3::ZERO),
                b("thigh", Some("root"), Vec3::new(0.0, 0.0, 90.0)),
                b("calf", Some("thigh"), Vec3::new(0.0, 0.0, -45.0)),
                b("foot", Some("calf"), Vec3::new(0.0, 0.0, -40.0)),
            ])
            .unwrap(),
        )
    }

    #[test]
    fn changing_a_local_moves_the_subtree() {
        let s = chain();
        let mut pose = Pose::new(s.clone());
        let thigh = s.find("thigh").unwrap();
        let foot = s.find("foot").unwrap();
        assert_eq!(pose.global(foot).translation, Vec3::new(0.0, 0.0, 5.0));
        // Rotate the thigh 90° about X: its children (pointing down, -Z) now point +Y.
        let mut l = pose.local(thigh);
        l.rotation = Quat::from_rotation_x(core::f32::consts::FRAC_PI_2);
        pose.set_local(thigh, l);
        let p = pose.global(foot).translation;
        assert!((p - Vec3::new(0.0, 85.0, 90.0)).length() < 1e-4, "{p}");
    }

    #[test]
    fn set_global_with_and_without_propagation() {
        let s = chain();
        let calf = s.find("calf").unwrap();
        let foot = s.find("foot").unwrap();
        let target = Transform::from_translation(Vec3::new(10.0, 0.0, 45.0));

        let mut pose = Pose::new(s.clone());
        pose.set_global(calf, target, true);
        // The foot keeps its local offset (0,0,-40) and moves with the calf.
        assert_eq!(pose.global(foot).translation, Vec3::new(10.0, 0.0, 5.0));
        assert_eq!(pose.local(calf).translation, Vec3::new(10.0, 0.0, -45.0));

        let mut pose = Pose::new(s);
        pose.set_global(calf, target, false);
        // The foot stays where it was in rig space.
        assert_eq!(pose.global(foot).translation, Vec3::new(0.0, 0.0, 5.0));
        assert_eq!(pose.local(foot).translation, Vec3::new(-10.0, 0.0, -40.0));
    }

    /// Bits of every local and global of `pose`.
    fn bits(pose: &mut Pose) -> Vec<[u32; 10]> {
        let locals: Vec<_> = pose.locals().iter().map(Transform::to_bits).collect();
        let globals = pose.globals().iter().map(Transform::to_bits);
        locals.into_iter().chain(globals).collect()
    }

    /// `start` with `globals` set on `bones` by [`Pose::set_chain_globals`], and `start` with
    /// them set by three [`Pose::set_global`] calls with propagation, in order.
    fn at_once_and_one_by_one(
        start: &Pose,
        bones: [BoneIndex; 3],
        globals: [Transform; 3],
    ) -> (Pose, Pose) {
        let mut at_once = start.clone();
        at_once.set_chain_globals(bones, globals);
        let mut one_by_one = start.clone();
        for (bone, g) in bones.into_iter().zip(globals) {
            one_by_one.set_global(bone, g, true);
        }
        (at_once, one_by_one)
    }

    #[test]
    fn a_chain_set_at_once_is_three_set_globals() {
        // Thigh, calf and foot bent into an L: the thigh at (5, 0, 90) turned 90° about X
        // (its −Z now points along +Y), the calf turned with it 45 cm along +Y at
        // (5, 45, 90), the foot unturned 40 cm straight down from there at (5, 45, 50).
        let s = chain();
        let [thigh, calf, foot] = ["thigh", "calf", "foot"].map(|n| s.find(n).unwrap());
        let turn = Quat::from_rotation_x(core::f32::consts::FRAC_PI_2);
        let globals = [
            Transform::from_translation_rotation(Vec3::new(5.0, 0.0, 90.0), turn),
            Transform::from_translation_rotation(Vec3::new(5.0, 45.0, 90.0), turn),
            Transform::from_translation(Vec3::new(5.0, 45.0, 50.0)),
        ];
        let (mut one_pass, mut three) =
            at_once_and_one_by_one(&Pose::new(s.clone()), [thigh, calf, foot], globals);
        assert_eq!(bits(&mut one_pass), bits(&mut three));
        // In its parent's frame the calf is 45 cm down the thigh's −Z, unturned; the foot is
        // 40 cm along the rig's −Z, which in the calf's turned frame is its −Y: (0, −40, 0),
        // turned back by −90° about X.
        let calf_local = one_pass.local(calf);
        assert!((calf_local.translation - Vec3::new(0.0, 0.0, -45.0)).length() < 1e-4);
        assert!(calf_local.rotation.angle_between(Quat::IDENTITY) < 1e-4);
        let foot_local = one_pass.local(foot);
        let (t, r) = (foot_local.translation, foot_local.rotation);
        assert!((t - Vec3::new(0.0, -40.0, 0.0)).length() < 1e-4, "{t}");
        assert!(r.angle_between(turn.inverse()) < 1e-4);
        // Moving the root 10 cm along +Y carries the whole chain along.
        let root = s.find("root").unwrap();
        one_pass.set_local(root, Transform::from_translation(Vec3::new(0.0, 10.0, 0.0)));
        let moved = one_pass.global(foot).translation;
        assert!(
            (moved - Vec3::new(5.0, 55.0, 50.0)).length() < 1e-4,
            "{moved}"
        );
    }

    #[test]
    fn a_chain_set_at_once_leaves_the_same_bones_stale() {
        // A leg with a toe below the foot, a twist bone beside the calf and an arm beside
        // the leg, all current (the root moved, then every global was read) when the chain
        // is set: the bones below the chain and beside it within the thigh's subtree must
        // end stale, the root and the arm current.
        let b = |name: &str, parent: &str, t: Vec3| Bone {
            name: name.into(),
            parent: Some(parent.into()),
            rest_local: Transform::from_translation(t),
        };
        let s = Arc::new(
            Skeleton::new(vec![
                Bone {
                    name: "root".into(),
                    parent: None,
                    rest_local: Transform::IDENTITY,
                },
                b("thigh", "root", Vec3::new(0.0, 0.0, 90.0)),
                b("calf", "thigh", Vec3::new(0.0, 0.0, -45.0)),
                b("foot", "calf", Vec3::new(0.0, 0.0, -40.0)),
                b("toe", "foot", Vec3::new(0.0, 15.0, -5.0)),
                b("twist", "thigh", Vec3::new(0.0, 0.0, -20.0)),
                b("arm", "root", Vec3::new(20.0, 0.0, 140.0)),
            ])
            .unwrap(),
        );
        let [root, thigh, calf, foot] =
            ["root", "thigh", "calf", "foot"].map(|n| s.find(n).unwrap());
        let turn = Quat::from_rotation_y(0.4);
        let globals = [
            Transform::from_translation_rotation(Vec3::new(1.0, 2.0, 91.0), turn),
            Transform::from_translation_rotation(Vec3::new(3.0, 2.0, 50.0), turn),
            Transform::from_translation(Vec3::new(4.0, 6.0, 10.0)),
        ];
        let mut start = Pose::new(s.clone());
        start.set_local(root, Transform::from_translation(Vec3::new(0.0, 5.0, 0.0)));
        let _ = start.globals();
        let (mut one_pass, mut three) =
            at_once_and_one_by_one(&start, [thigh, calf, foot], globals);
        assert_eq!(one_pass.stale, three.stale);
        let stale: Vec<bool> = (0..s.len()).map(|i| one_pass.is_stale(i)).collect();
        let name_of = |i: usize| s.names()[i].as_str();
        for (i, &st) in stale.iter().enumerate() {
            let want = matches!(name_of(i), "toe" | "twist");
            assert_eq!(st, want, "{}", name_of(i));
        }
        assert_eq!(bits(&mut one_pass), bits(&mut three));
    }

    #[test]
    fn a_limb_set_with_its_locals_is_the_limb_set_at_once() {
        // The L-shaped leg of the test above, under a root moved and turned first, so that
        // the thigh's parent global is not the identity.
        let s = chain();
        let [root, thigh, calf, foot] =
            ["root", "thigh", "calf", "foot"].map(|n| s.find(n).unwrap());
        let mut start = Pose::new(s.clone());
        start.set_local(
            root,
            Transform::new(
                Vec3::new(3.0, -2.0, 1.0),
                Quat::from_rotation_z(0.4),
                Vec3::splat(1.5),
            ),
        );
        let turn = Quat::from_rotation_x(core::f32::consts::FRAC_PI_2);
        let globals = [
            Transform::from_translation_rotation(Vec3::new(5.0, 0.0, 90.0), turn),
            Transform::from_translation_rotation(Vec3::new(5.0, 45.0, 90.0), turn),
            Transform::from_translation(Vec3::new(5.0, 45.0, 50.0)),
        ];
        let [ga, gb, gc] = globals;
        let locals = [
            ga.relative_to(&start.clone().global(root)),
            gb.relative_to(&ga),
            gc.relative_to(&gb),
        ];
        let mut with_locals = start.clone();
        assert!(with_locals.set_chain_with_locals([thigh, calf, foot], globals, locals));
        let mut at_once = start.clone();
        at_once.set_chain_globals([thigh, calf, foot], globals);
        assert_eq!(bits(&mut with_locals), bits(&mut at_once));
        let locals_of = |p: &Pose| {
            p.locals()
                .iter()
                .map(Transform::to_bits)
                .collect::<Vec<_>>()
        };
        assert_eq!(locals_of(&with_locals), locals_of(&at_once));
        // Bones that are not a limb: nothing changes.
        let mut not_a_limb = start.clone();
        assert!(!not_a_limb.set_chain_with_locals([root, calf, thigh], globals, locals));
        assert_eq!(bits(&mut not_a_limb), bits(&mut start));
        assert_eq!(locals_of(&not_a_limb), locals_of(&start));
    }

    #[test]
    fn bones_that_are_not_a_chain_are_set_one_by_one() {
        // Root, calf and thigh: not parent → child → grandchild in that order.
        let s = chain();
        let [root, thigh, calf] = ["root", "thigh", "calf"].map(|n| s.find(n).unwrap());
        let globals = [
            Transform::from_translation(Vec3::new(1.0, 0.0, 0.0)),
            Transform::from_translation(Vec3::new(2.0, 0.0, 40.0)),
            Transform::from_translation(Vec3::new(3.0, 0.0, 80.0)),
        ];
        let (mut at_once, mut three) =
            at_once_and_one_by_one(&Pose::new(s), [root, calf, thigh], globals);
        assert_eq!(bits(&mut at_once), bits(&mut three));
    }

    #[test]
    fn globals_pass_matches_lazy_reads() {
        let s = chain();
        let mut a = Pose::new(s.clone());
        let thigh = s.find("thigh").unwrap();
        a.set_local(
            thigh,
            Transform::from_translation_rotation(
                Vec3::new(1.0, 2.0, 3.0),
                Quat::from_rotation_y(0.3),
            ),
        );
        let mut b = a.clone();
        let all = a.globals().to_vec();
        for (i, g) in all.iter().enumerate() {
            assert_eq!(*g, b.global(BoneIndex(i as u32)));
        }
    }

    /// A tree of 150 bones in depth-first order: a spine of 100 (each 1 cm above its
    /// parent) and a branch of 50 off bone 40 (each 1 cm along +X), so subtrees span the
    /// stale flags' 64-bone words.
    fn long_tree() -> Arc<Skeleton> {
        let b = |i: usize, parent: Option<usize>, t: Vec3| Bone {
            name: format!("b{i}"),
            parent: parent.map(|p| format!("b{p}")),
            rest_local: Transform::from_translation(t),
        };
        let mut bones = vec![b(0, None, Vec3::ZERO)];
        for i in 1..=40 {
            bones.push(b(i, Some(i - 1), Vec3::Z));
        }
        // The branch right after bone 40 (depth-first), then the spine goes on from 40.
        bones.push(b(41, Some(40), Vec3::X));
        for i in 42..91 {
            bones.push(b(i, Some(i - 1), Vec3::X));
        }
        bones.push(b(91, Some(40), Vec3::Z));
        for i in 92..150 {
            bones.push(b(i, Some(i - 1), Vec3::Z));
        }
        Arc::new(Skeleton::new(bones).unwrap())
    }

    #[test]
    fn stale_flags_across_words_follow_every_subtree() {
        let s = long_tree();
        let up = |cm: f32| Transform::from_translation(Vec3::new(0.0, 0.0, cm));
        for bone in [0, 1, 40, 41, 63, 64, 90, 91, 127, 128, 149] {
            let at = BoneIndex(bone);
            let mut lazy = Pose::new(s.clone());
            let _ = lazy.globals();
            lazy.set_local(at, lazy.local(at) * up(1000.0));
            // Every bone of the subtree moved up 1000 cm, every other bone stayed: read
            // lazily, one by one, in reverse storage order.
            let end = s.subtree_end(at);
            for i in (0..150).rev() {
                let rest = s.rest_global(BoneIndex(i as u32)).translation;
                let moved = (bone as usize..end).contains(&i);
                let want = rest + Vec3::Z * if moved { 1000.0 } else { 0.0 };
                let got = lazy.global(BoneIndex(i as u32)).translation;
                assert!((got - want).length() < 1e-3, "bone {i} after {bone}: {got}");
            }
            // Set globally with propagation: the subtree follows, the rest stays.
            let mut set = Pose::new(s.clone());
            let g = set.global(at);
            set.set_global(at, up(-500.0) * g, true);
            let all = set.clone().globals().to_vec();
            for (i, g) in all.iter().enumerate() {
                let rest = s.rest_global(BoneIndex(i as u32)).translation;
                let moved = (bone as usize..end).contains(&i);
                let want = rest - Vec3::Z * if moved { 500.0 } else { 0.0 };
                assert!(
                    (g.translation - want).length() < 1e-3,
                    "bone {i} set at {bone}"
                );
                assert_eq!(*g, set.global(BoneIndex(i as u32)));
            }
        }
    }
}
