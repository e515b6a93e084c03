//! [`Skeleton`]: named bones, their hierarchy and their rest (initial) pose.
//!
//! Bones are stored in depth-first pre-order: a parent always comes before its children,
//! and the descendants of bone `i` are exactly the bones `i + 1 .. subtree_end(i)`. That
//! makes "recompute globals" a single forward pass and "mark the subtree dirty" a range.

use crate::transform::Transform;
use std::collections::HashMap;
use std::fmt;

/// Index of a bone in a [`Skeleton`] (depth-first pre-order).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct BoneIndex(pub u32);

impl BoneIndex {
    /// The index as a `usize`, for slicing.
    #[must_use]
    pub const fn get(self) -> usize {
        self.0 as usize
    }
}

/// One bone as described by a skeleton file, before validation.
#[derive(Clone, Debug, PartialEq)]
pub struct Bone {
    /// Unique name, as graphs refer to it (`bone("foot_l")`).
    pub name: String,
    /// Name of the parent bone; `None` for a root.
    pub parent: Option<String>,
    /// Rest (initial) transform relative to the parent, centimetres.
    pub rest_local: Transform,
}

/// Why a list of bones is not a valid skeleton. `bone` is the position of the offending
/// bone in the list given to [`Skeleton::new`], so a loader can point at its source.
#[derive(Clone, Debug, PartialEq)]
pub enum SkeletonError {
    /// The skeleton has no bones.
    Empty,
    /// Two bones share a name.
    DuplicateName {
        /// Position of the second bone with this name.
        bone: usize,
        /// Position of the first.
        first: usize,
        /// The shared name.
        name: String,
    },
    /// A bone names a parent that does not exist.
    UnknownParent {
        /// Position of the bone.
        bone: usize,
        /// The missing parent's name.
        parent: String,
        /// The closest existing name, if one is close.
        suggestion: Option<String>,
    },
    /// Following parents from this bone comes back to it.
    Cycle {
        /// Position of a bone on the cycle.
        bone: usize,
        /// Names along the cycle, starting and ending at the same bone.
        path: Vec<String>,
    },
    /// A rest rotation is not a unit quaternion (|q| off by more than 1e-3), or a value is
    /// not finite.
    NotNormalized {
        /// Position of the bone.
        bone: usize,
        /// The rotation's length.
        length: f32,
    },
    /// A translation, rotation or scale component is NaN or infinite.
    NotFinite {
        /// Position of the bone.
        bone: usize,
    },
}

impl fmt::Display for SkeletonError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SkeletonError::Empty => write!(f, "the skeleton has no bones"),
            SkeletonError::DuplicateName { name, .. } => {
                write!(
                    f,
                    "bone name `{name}` is used twice; bone names must be unique"
                )
            }
            SkeletonError::UnknownParent {
                parent, suggestion, ..
            } => {
                write!(f, "unknown parent bone `{parent}`")?;
                if let Some(s) = suggestion {
                    write!(f, "; did you mean `{s}`?")?;
                }
                Ok(())
            }
            SkeletonError::Cycle { path, .. } => {
                write!(f, "the parent chain loops: {}", path.join(" → "))
            }
            SkeletonError::NotNormalized { length, .. } => write!(
                f,
                "rest rotation is not a unit quaternion (length {length}); \
                 normalise it or write it as euler(x, y, z)"
            ),
            SkeletonError::NotFinite { .. } => {
                write!(f, "rest transform has a NaN or infinite component")
            }
        }
    }
}

impl std::error::Error for SkeletonError {}

/// An immutable, validated bone hierarchy with its rest pose.
#[derive(Clone, Debug)]
pub struct Skeleton {
    names: Vec<String>,
    parents: Vec<Option<BoneIndex>>,
    rest_local: Vec<Transform>,
    rest_global: Vec<Transform>,
    subtree_end: Vec<u32>,
    /// `children[child_start[i]..child_start[i + 1]]` are bone `i`'s direct children.
    child_start: Vec<u32>,
    children: Vec<BoneIndex>,
    by_name: HashMap<String, BoneIndex>,
    /// Position of each bone in the list given to [`Skeleton::new`].
    source_order: Vec<usize>,
}

impl Skeleton {
    /// Validates `bones` (unique names, known parents, no cycles, unit rotations, finite
    /// values) and orders them depth-first, children in the order given.
    ///
    /// # Errors
    /// Every problem found, each naming the bone's position in `bones`.
    pub fn new(bones: Vec<Bone>) -> Result<Self, Vec<SkeletonError>> {
        if bones.is_empty() {
            return Err(vec![SkeletonError::Empty]);
        }
        let mut errors = Vec::new();
        let mut index: HashMap<&str, usize> = HashMap::new();
        for (i, b) in bones.iter().enumerate() {
            if let Some(&first) = index.get(b.name.as_str()) {
                errors.push(SkeletonError::DuplicateName {
                    bone: i,
                    first,
                    name: b.name.clone(),
                });
            } else {
                index.insert(&b.name, i);
            }
            let t = &b.rest_local;
            if !t.is_finite() {
                errors.push(SkeletonError::NotFinite { bone: i });
            } else if (t.rotation.length() - 1.0).abs() > 1e-3 {
                errors.push(SkeletonError::NotNormalized {
                    bone: i,
                    length: t.rotation.length(),
                });
            }
        }
        let mut parent_of: Vec<Option<usize>> = vec![None; bones.len()];
        for (i, b) in bones.iter().enumerate() {
            if let Some(p) = &b.parent {
                match index.get(p.as_str()) {
                    Some(&pi) => parent_of[i] = Some(pi),
                    None => errors.push(SkeletonError::UnknownParent {
                        bone: i,
                        parent: p.clone(),
                        suggestion: closest(p, bones.iter().map(|b| b.name.as_str())),
                    }),
                }
            }
        }
        // Cycles: walk up from each bone; more steps than bones means a loop.
        let mut reported = vec![false; bones.len()];
        for start in 0..bones.len() {
            let mut path = vec![start];
            let mut cur = start;
            while let Some(p) = parent_of[cur] {
                if let Some(pos) = path.iter().position(|&x| x == p) {
                    let cycle = &path[pos..];
                    if !cycle.iter().any(|&c| reported[c]) {
                        for &c in cycle {
                            reported[c] = true;
                        }
                        let mut names: Vec<String> =
                            cycle.iter().map(|&c| bones[c].name.clone()).collect();
                        names.push(bones[p].name.clone());
                        errors.push(SkeletonError::Cycle {
                            bone: cycle[0],
                            path: names,
                        });
                    }
                    break;
                }
                path.push(p);
                cur = p;
            }
        }
        if !errors.is_empty() {
            return Err(errors);
        }

        // Depth-first pre-order, roots and children in file order.
        let mut kids: Vec<Vec<usize>> = vec![Vec::new(); bones.len()];
        let mut roots = Vec::new();
        for (i, p) in parent_of.iter().enumerate() {
            match p {
                Some(p) => kids[*p].push(i),
                None => roots.push(i),
            }
        }
        let mut order = Vec::with_capacity(bones.len());
        let mut stack: Vec<usize> = roots.into_iter().rev().collect();
        while let Some(b) = stack.pop() {
            order.push(b);
            stack.extend(kids[b].iter().rev());
        }
        let mut new_index = vec![0usize; bones.len()];
        for (new, &old) in order.iter().enumerate() {
            new_index[old] = new;
        }
        let n = bones.len();
        let mut names = Vec::with_capacity(n);
        let mut parents = Vec::with_capacity(n);
        let mut rest_local = Vec::with_capacity(n);
        for &old in &order {
            names.push(bones[old].name.clone());
            parents.push(parent_of[old].map(|p| BoneIndex(new_index[p] as u32)));
            rest_local.push(bones[old].rest_local);
        }
        let mut rest_global = rest_local.clone();
        for i in 0..n {
            if let Some(p) = parents[i] {
                rest_global[i] = rest_global[p.get()] * rest_local[i];
            }
        }
        let mut subtree_end: Vec<u32> = (1..=n as u32).collect();
        for i in (0..n).rev() {
            if let Some(p) = parents[i] {
                subtree_end[p.get()] = subtree_end[p.get()].max(subtree_end[i]);
            }
        }
        let mut child_start = Vec::with_capacity(n + 1);
        let mut children = Vec::new();
        for &old in &order {
            child_start.push(children.len() as u32);
            children.extend(kids[old].iter().map(|&k| BoneIndex(new_index[k] as u32)));
        }
        child_start.push(children.len() as u32);
        let by_name = names
            .iter()
            .enumerate()
            .map(|(i, s)| (s.clone(), BoneIndex(i as u32)))
            .collect();
        Ok(Self {
            names,
            parents,
            rest_local,
            rest_global,
            subtree_end,
            child_start,
            children,
            by_name,
            source_order: order,
        })
    }

    /// Number of bones.
    #[must_use]
    pub fn len(&self) -> usize {
        self.names.len()
    }

    /// Always false: a skeleton has at least one bone.
    #[must_use]
    pub fn is_empty(&self) -> bool {
        self.names.is_empty()
    }

    /// The bone called `name`, if any. A hash lookup: for load and instantiation time,
    /// never per frame.
    #[must_use]
    pub fn find(&self, name: &str) -> Option<BoneIndex> {
        self.by_name.get(name).copied()
    }

    /// The existing bone name closest to `name`, for "did you mean" hints.
    #[must_use]
    pub fn suggest(&self, name: &str) -> Option<String> {
        closest(name, self.names.iter().map(String::as_str))
    }

    /// A bone's name.
    #[must_use]
    pub fn name(&self, bone: BoneIndex) -> &str {
        &self.names[bone.get()]
    }

    /// All bone names in storage (depth-first) order.
    #[must_use]
    pub fn names(&self) -> &[String] {
        &self.names
    }

    /// A bone's parent, `None` for a root.
    #[must_use]
    pub fn parent(&self, bone: BoneIndex) -> Option<BoneIndex> {
        self.parents[bone.get()]
    }

    /// A bone's direct children, in file order.
    #[must_use]
    pub fn children(&self, bone: BoneIndex) -> &[BoneIndex] {
        let i = bone.get();
        &self.children[self.child_start[i] as usize..self.child_start[i + 1] as usize]
    }

    /// One past the last descendant of `bone`: its descendants are
    /// `bone + 1 .. subtree_end(bone)`.
    #[must_use]
    pub fn subtree_end(&self, bone: BoneIndex) -> usize {
        self.subtree_end[bone.get()] as usize
    }

    /// Rest transform relative to the parent (centimetres).
    #[must_use]
    pub fn rest_local(&self, bone: BoneIndex) -> Transform {
        self.rest_local[bone.get()]
    }

    /// Rest transform in rig space (centimetres).
    #[must_use]
    pub fn rest_global(&self, bone: BoneIndex) -> Transform {
        self.rest_global[bone.get()]
    }

    /// All rest local transforms, in storage order.
    #[must_use]
    pub fn rest_locals(&self) -> &[Transform] {
        &self.rest_local
    }

    /// All rest global transforms, in storage order.
    #[must_use]
    pub fn rest_globals(&self) -> &[Transform] {
        &self.rest_global
    }

    /// Position, in the list given to [`Skeleton::new`], of the bone now stored at `bone`.
    #[must_use]
    pub fn source_position(&self, bone: BoneIndex) -> usize {
        self.source_order[bone.get()]
    }
}

/// The candidate closest to `name` by edit distance, if it is close enough to be a
/// plausible typo (at most a third of the name's length, at least one edit).
#[must_use]
pub fn closest<'a>(name: &str, candidates: impl Iterator<Item = &'a str>) -> Option<String> {
    let limit = (name.chars().count() / 3).max(1);
    candidates
        .map(|c| (levenshtein(&name.to_lowercase(), &c.to_lowercase()), c))
        .filter(|(d, _)| *d <= limit)
        .min_by_key(|(d, _)| *d)
        .map(|(_, c)| c.to_string())
}

/// Edit distance. Written here so the runtime crates stay free of dependencies beyond glam;
/// the loader crates use `strsim` for the same job.
fn levenshtein(a: &str, b: &str) -> usize {
    let b: Vec<char> = b.chars().collect();
    let mut prev: Vec<usize> = (0..=b.len()).collect();
    let mut cur = vec![0; b.len() + 1];
    for (i, ca) in a.chars().enumerate() {
        cur[0] = i + 1;
        for (j, &cb) in b.iter().enumerate() {
            let cost = usize::from(ca != cb);
            cur[j + 1] = (prev[j] + cost).min(prev[j + 1] + 1).min(cur[j] + 1);
        }
        std::mem::swap(&mut prev, &mut cur);
    }
    prev[b.len()]
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::Vec3;

    fn bone(name: &str, parent: Option<&str>, z: f32) -> Bone {
        Bone {
            name: name.into(),
            parent: parent.map(Into::into),
            rest_local: Transform::from_translation(Vec3::new(0.0, 0.0, z)),
        }
    }

    #[test]
    fn orders_depth_first_and_composes_rest_globals() {
        // Children listed before their parents on purpose.
        let s = Skeleton::new(vec![
            bone("calf", Some("thigh"), -40.0),
            bone("root", None, 0.0),
            bone("thigh", Some("pelvis"), -5.0),
            bone("pelvis", Some("root"), 95.0),
            bone("spine", Some("pelvis"), 10.0),
        ])
        .unwrap();
        assert_eq!(s.names(), ["root", "pelvis", "thigh", "calf", "spine"]);
        let calf = s.find("calf").unwrap();
        assert_eq!(s.rest_global(calf).translation, Vec3::new(0.0, 0.0, 50.0));
        let pelvis = s.find("pelvis").unwrap();
        assert_eq!(s.subtree_end(pelvis), 5);
        assert_eq!(s.subtree_end(s.find("thigh").unwrap()), 4);
        assert_eq!(s.children(pelvis).len(), 2);
        assert_eq!(s.source_position(calf), 0);
    }

    #[test]
    fn reports_every_problem() {
        let mut bad = bone("b", Some("a"), 1.0);
        bad.rest_local.rotation = glam::Quat::from_xyzw(0.0, 0.0, 0.0, 2.0);
        let errors = Skeleton::new(vec![
            bone("a", None, 0.0),
            bad,
            bone("a", None, 0.0),
            bone("c", Some("pelvsi"), 0.0),
            bone("x", Some("y"), 0.0),
            bone("y", Some("x"), 0.0),
        ])
        .unwrap_err();
        assert!(errors.contains(&SkeletonError::DuplicateName {
            bone: 2,
            first: 0,
            name: "a".into()
        }));
        assert!(errors.iter().any(|e| matches!(e, SkeletonError::NotNormalized { bone: 1, length } if (*length - 2.0).abs() < 1e-6)));
        assert!(
            errors
                .iter()
                .any(|e| matches!(e, SkeletonError::UnknownParent { bone: 3, .. }))
        );
        let cycle = errors
            .iter()
            .find(|e| matches!(e, SkeletonError::Cycle { .. }))
            .unwrap();
        assert_eq!(cycle.to_string(), "the parent chain loops: x → y → x");
    }

    #[test]
    fn suggests_close_names_only() {
        assert_eq!(
            closest("foot_k", ["foot_l", "hand_l"].into_iter()),
            Some("foot_l".into())
        );
        assert_eq!(closest("banana", ["foot_l", "hand_l"].into_iter()), None);
    }
}
