//! Skeleton files (`graphs/skeletons/*.ron`): bones with parents and rest transforms, and
//! sole contact points for ground-contact metrics.
//!
//! ```ron
//! Skeleton(
//!     version: 1,
//!     name: "mannequin",
//!     bones: [
//!         (name: "root", parent: None),
//!         (name: "pelvis", parent: "root", translation: (0.0, 0.0, 95.0)),
//!         (name: "thigh_l", parent: "pelvis", translation: (9.5, 0.0, -3.0),
//!          rotation: (0.0, -0.7071068, 0.0, 0.7071068)),
//!     ],
//!     contacts: [ (name: "heel_l", bone: "foot_l", offset: (0.0, 3.0, -13.5)) ],
//! )
//! ```
//! `translation` (cm), `rotation` (unit quaternion `(x, y, z, w)` or `euler(x, y, z)` in
//! degrees) and `scale` are the rest transform relative to the parent; each is optional.

use crate::diagnostic::{Diagnostic, Diagnostics, FileId, Loc, SourceMap};
use crate::reader::{self, Bump, Spanned, Value};
use glam::{Quat, Vec3};
use std::path::Path;
use std::sync::Arc;
use strider_core::{Bone, Skeleton, SkeletonError, Transform};

/// A point on a foot's sole, in the bone's local frame, used to measure ground contact.
#[derive(Clone, Debug, PartialEq)]
pub struct ContactPoint {
    /// Its name (`heel_l`).
    pub name: String,
    /// The bone it is attached to.
    pub bone: String,
    /// Offset in the bone's local frame, cm.
    pub offset: Vec3,
}

/// A loaded skeleton file.
#[derive(Clone, Debug)]
pub struct SkeletonFile {
    /// The skeleton's name.
    pub name: String,
    /// The validated skeleton.
    pub skeleton: Arc<Skeleton>,
    /// Sole contact points.
    pub contacts: Vec<ContactPoint>,
}

/// Reads and validates a skeleton file.
///
/// # Errors
/// Every syntax and validation problem (unknown parent, duplicate name, cycle,
/// non-normalised rotation, unknown contact bone), each with `path:line:col`.
pub fn load_skeleton(path: &Path) -> Result<SkeletonFile, Vec<Diagnostic>> {
    match std::fs::read_to_string(path) {
        Ok(text) => load_skeleton_str(path, text),
        Err(e) => {
            let mut d = Diagnostics::default();
            d.file_error(path, format!("cannot read the skeleton file: {e}"))
                .emit();
            Err(d.into_vec())
        }
    }
}

/// Parses skeleton `text` as if read from `path`.
///
/// # Errors
/// As [`load_skeleton`].
pub fn load_skeleton_str(path: &Path, text: String) -> Result<SkeletonFile, Vec<Diagnostic>> {
    let mut sources = SourceMap::default();
    let file = sources.add(path, text);
    let mut diags = Diagnostics::default();
    let arena = Bump::new();
    let root = match reader::parse(sources.text(file), &arena) {
        Ok(r) => r,
        Err(e) => {
            diags
                .error(
                    &sources,
                    Loc { file, span: e.span },
                    format!("RON syntax: {}", e.message),
                )
                .emit();
            return Err(diags.into_vec());
        }
    };
    let mut r = SkelReader {
        sources: &sources,
        diags: &mut diags,
        file,
    };
    let result = r.skeleton(&root);
    match result {
        Some(s) if diags.is_empty() => Ok(s),
        _ => Err(diags.into_vec()),
    }
}

struct SkelReader<'a> {
    sources: &'a SourceMap,
    diags: &'a mut Diagnostics,
    file: FileId,
}

impl SkelReader<'_> {
    fn err(&mut self, span: reader::Span, msg: impl Into<String>) -> crate::diagnostic::Report<'_> {
        self.diags.error(
            self.sources,
            Loc {
                file: self.file,
                span,
            },
            msg,
        )
    }

    fn numbers<const N: usize>(&mut self, v: &Spanned<Value>, what: &str) -> Option<[f32; N]> {
        if let Value::Tuple(None, items) = &v.value
            && items.len() == N
        {
            let mut out = [0.0; N];
            for (o, item) in out.iter_mut().zip(items.iter()) {
                *o = match item.value {
                    Value::Int(i) => i as f32,
                    Value::Float(f) => f as f32,
                    _ => {
                        self.err(item.span, format!("expected a number in {what}"))
                            .emit();
                        return None;
                    }
                };
            }
            return Some(out);
        }
        self.err(v.span, format!("expected {what} as a tuple of {N} numbers"))
            .emit();
        None
    }

    fn rotation(&mut self, v: &Spanned<Value>) -> Option<Quat> {
        if let Value::Tuple(Some(n), items) = v.value
            && n.value == "euler"
        {
            let inner = Spanned {
                value: Value::Tuple(None, items),
                span: v.span,
            };
            let [x, y, z] = self.numbers::<3>(&inner, "euler angles (degrees)")?;
            return Some(strider_core::euler::quat_from_euler(
                Vec3::new(x, y, z),
                strider_core::EulerOrder::XYZ,
            ));
        }
        let [x, y, z, w] = self.numbers::<4>(v, "a rotation (x, y, z, w) or euler(x, y, z)")?;
        Some(Quat::from_xyzw(x, y, z, w))
    }

    fn skeleton(&mut self, root: &Spanned<Value>) -> Option<SkeletonFile> {
        let Value::Struct(Some(name), fields) = &root.value else {
            self.err(root.span, "a skeleton file holds one `Skeleton( ... )`")
                .emit();
            return None;
        };
        if name.value != "Skeleton" {
            self.err(
                name.span,
                format!(
                    "a skeleton file starts with `Skeleton(`, found `{}(`",
                    name.value
                ),
            )
            .emit();
            return None;
        }
        let mut skel_name = String::new();
        let mut bones: Vec<Bone> = Vec::new();
        let mut bone_spans = Vec::new();
        let mut contacts = Vec::new();
        let mut contact_spans = Vec::new();
        for (f, fv) in fields.iter() {
            match f.value {
                "version" => {
                    if !matches!(fv.value, Value::Int(1)) {
                        self.err(fv.span, "unsupported skeleton format version")
                            .hint("this build reads version 1")
                            .emit();
                    }
                }
                "name" => {
                    if let Value::String(s) = &fv.value {
                        skel_name = s.to_string();
                    }
                }
                "bones" => {
                    let Value::List(items) = &fv.value else {
                        self.err(fv.span, "expected `bones: [ ... ]`").emit();
                        continue;
                    };
                    for item in items.iter() {
                        if let Some(b) = self.bone(item) {
                            bones.push(b);
                            bone_spans.push(item.span);
                        }
                    }
                }
                "contacts" => {
                    let Value::List(items) = &fv.value else {
                        self.err(fv.span, "expected `contacts: [ ... ]`").emit();
                        continue;
                    };
                    for item in items.iter() {
                        if let Some(c) = self.contact(item) {
                            contacts.push(c);
                            contact_spans.push(item.span);
                        }
                    }
                }
                other => {
                    let hint = crate::suggest(other, ["version", "name", "bones", "contacts"])
                        .map(|s| format!("did you mean `{s}`?"));
                    self.err(f.span, format!("unknown field `{other}` in Skeleton"))
                        .maybe_hint(hint)
                        .emit();
                }
            }
        }
        let skeleton = match Skeleton::new(bones) {
            Ok(s) => s,
            Err(errors) => {
                for e in errors {
                    let span = match &e {
                        SkeletonError::Empty => root.span,
                        SkeletonError::DuplicateName { bone, .. }
                        | SkeletonError::UnknownParent { bone, .. }
                        | SkeletonError::Cycle { bone, .. }
                        | SkeletonError::NotNormalized { bone, .. }
                        | SkeletonError::NotFinite { bone } => bone_spans[*bone],
                    };
                    self.err(span, e.to_string()).emit();
                }
                return None;
            }
        };
        for (c, span) in contacts.iter().zip(contact_spans) {
            if skeleton.find(&c.bone).is_none() {
                let hint = skeleton
                    .suggest(&c.bone)
                    .map(|s| format!("did you mean `{s}`?"));
                self.err(
                    span,
                    format!("contact point `{}` is on unknown bone `{}`", c.name, c.bone),
                )
                .maybe_hint(hint)
                .emit();
            }
        }
        Some(SkeletonFile {
            name: skel_name,
            skeleton: Arc::new(skeleton),
            contacts,
        })
    }

    fn bone(&mut self, v: &Spanned<Value>) -> Option<Bone> {
        let Value::Struct(None, fields) = &v.value else {
            self.err(v.span, "a bone is `(name: \"...\", parent: \"...\" or None, translation: .., rotation: ..)`").emit();
            return None;
        };
        let mut name = None;
        let mut parent = None;
        let mut t = Transform::IDENTITY;
        for (f, fv) in fields.iter() {
            match (f.value, &fv.value) {
                ("name", Value::String(s)) => name = Some(s.to_string()),
                ("parent", Value::String(s)) => parent = Some(s.to_string()),
                ("parent", Value::Ident(s)) if *s == "None" => parent = None,
                ("translation", _) => {
                    t.translation = Vec3::from_array(self.numbers::<3>(fv, "a translation (cm)")?)
                }
                ("rotation", _) => t.rotation = self.rotation(fv)?,
                ("scale", _) => t.scale = Vec3::from_array(self.numbers::<3>(fv, "a scale")?),
                ("name" | "parent", other) => {
                    let found = other.describe();
                    self.err(
                        fv.span,
                        format!(
                            "expected `{}` as a string in quotes, found {found}",
                            f.value
                        ),
                    )
                    .emit();
                    return None;
                }
                (other, _) => {
                    let hint = crate::suggest(
                        other,
                        ["name", "parent", "translation", "rotation", "scale"],
                    )
                    .map(|s| format!("did you mean `{s}`?"));
                    self.err(f.span, format!("unknown field `{other}` in a bone"))
                        .maybe_hint(hint)
                        .emit();
                }
            }
        }
        let Some(name) = name else {
            self.err(v.span, "a bone needs a `name:`").emit();
            return None;
        };
        Some(Bone {
            name,
            parent,
            rest_local: t,
        })
    }

    fn contact(&mut self, v: &Spanned<Value>) -> Option<ContactPoint> {
        let Value::Struct(None, fields) = &v.value else {
            self.err(
                v.span,
                "a contact point is `(name: \"...\", bone: \"...\", offset: (x, y, z))`",
            )
            .emit();
            return None;
        };
        let (mut name, mut bone, mut offset) = (None, None, Vec3::ZERO);
        for (f, fv) in fields.iter() {
            match (f.value, &fv.value) {
                ("name", Value::String(s)) => name = Some(s.to_string()),
                ("bone", Value::String(s)) => bone = Some(s.to_string()),
                ("offset", _) => {
                    offset = Vec3::from_array(self.numbers::<3>(fv, "an offset (cm)")?)
                }
                (other, _) => {
                    self.err(
                        f.span,
                        format!("unexpected field `{other}` in a contact point"),
                    )
                    .emit();
                }
            }
        }
        match (name, bone) {
            (Some(name), Some(bone)) => Some(ContactPoint { name, bone, offset }),
            _ => {
                self.err(v.span, "a contact point needs `name:` and `bone:`")
                    .emit();
                None
            }
        }
    }
}
