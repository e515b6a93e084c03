//! Overrides files: values for a graph's tunable variables, kept apart from the graph so
//! that the graph file itself is never rewritten. The inspector exports them;
//! `strider run` / `strider report --overrides FILE` and the inspector read them.
//!
//! The format is a RON map from variable name to value, in any order:
//!
//! ```ron
//! // locomotion tuned for a long stride
//! {
//!     "MaxFootStrideLength": 80.0,   // Float: a number (an integer is accepted)
//!     "GridCount": 5,                // Int: a whole number
//!     "DebugDrawEnabled": false,     // Bool
//! }
//! ```
//!
//! Values are written in the variable's unit (centimetres, seconds, degrees, as the graph
//! declares). Only tunable variables of type `Float`, `Int`, `Bool` and `Vec3` (`(x, y, z)`)
//! may be given. A value outside the variable's range is accepted (ranges are the sliders'
//! bounds, not limits). Every problem is reported with `path:line:col`.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};
use strider_graph::Diagnostic;
use strider_graph::reader::{self, Bump, LineIndex, Span, Spanned, Value as Ron};
use strider_nodes::{Value, ValueType};
use strider_vm::{Instance, Program, VariableId};

/// One value of an overrides file.
#[derive(Clone, Debug, PartialEq)]
pub struct Override {
    /// The tunable variable it sets.
    pub variable: VariableId,
    /// Its name, as written.
    pub name: String,
    /// The value, of the variable's type.
    pub value: Value,
}

/// The values an overrides file gives, checked against a program, in file order.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Overrides {
    /// One entry per name in the file.
    pub entries: Vec<Override>,
}

impl Overrides {
    /// Reads and checks the overrides file at `path` against `program`'s tunables.
    ///
    /// # Errors
    /// Every problem found (unreadable file, syntax, unknown or non-tunable variable, wrong
    /// type, duplicate name), each with `path:line:col` and a hint where one helps.
    pub fn load(path: &Path, program: &Program) -> Result<Overrides, Vec<Diagnostic>> {
        match std::fs::read_to_string(path) {
            Ok(text) => Overrides::parse(path, &text, program),
            Err(e) => Err(vec![diagnostic(
                path,
                (1, 1),
                format!("cannot read the overrides file: {e}"),
                None,
            )]),
        }
    }

    /// Checks overrides `text` as if read from `path` (used in messages only).
    ///
    /// # Errors
    /// As [`Overrides::load`].
    pub fn parse(path: &Path, text: &str, program: &Program) -> Result<Overrides, Vec<Diagnostic>> {
        let lines = LineIndex::new(text);
        let at = |span: Span| lines.line_col(span.start);
        let arena = Bump::new();
        let root = reader::parse(text, &arena).map_err(|e| {
            vec![diagnostic(
                path,
                at(e.span),
                e.message,
                Some("an overrides file is a RON map: { \"Name\": value, ... }".to_string()),
            )]
        })?;
        let Ron::Map(items) = root.value else {
            return Err(vec![diagnostic(
                path,
                at(root.span),
                format!(
                    "expected a map of variable values, found {}",
                    root.value.describe()
                ),
                Some("write { \"Name\": value, ... }".to_string()),
            )]);
        };
        let mut entries = Vec::new();
        let mut errors = Vec::new();
        for (key, value) in items {
            let Ron::String(name) = &key.value else {
                errors.push(diagnostic(
                    path,
                    at(key.span),
                    format!(
                        "expected a variable name in quotes, found {}",
                        key.value.describe()
                    ),
                    None,
                ));
                continue;
            };
            match entry(program, name, value) {
                Ok(o) if entries.iter().any(|e: &Override| e.variable == o.variable) => {
                    errors.push(diagnostic(
                        path,
                        at(key.span),
                        format!("`{name}` is given twice"),
                        Some("keep one value per variable".to_string()),
                    ));
                }
                Ok(o) => entries.push(o),
                Err((span, message, hint)) => {
                    let span = if span == Span::default() {
                        key.span
                    } else {
                        span
                    };
                    errors.push(diagnostic(path, at(span), message, hint));
                }
            }
        }
        if errors.is_empty() {
            Ok(Overrides { entries })
        } else {
            Err(errors)
        }
    }

    /// The current values of every tunable variable of `instance` that an overrides file
    /// can hold, in declaration order.
    #[must_use]
    pub fn from_instance(instance: &Instance) -> Overrides {
        let program = instance.program();
        let entries = program
            .variables()
            .iter()
            .enumerate()
            .filter(|(_, v)| v.tunable.is_some() && writable(v.ty))
            .map(|(i, v)| {
                let id = VariableId(i as u32);
                Override {
                    variable: id,
                    name: v.name.clone(),
                    value: instance.variable(id),
                }
            })
            .collect();
        Overrides { entries }
    }

    /// Sets every value on `instance` (which must run the program the overrides were
    /// checked against). `construction` has already run when an instance exists: call
    /// `Instance::rebind` afterwards (it keeps tunables) when what it derives from
    /// tunables must follow.
    pub fn apply(&self, instance: &mut Instance) {
        for e in &self.entries {
            // Checked against the program's types when read: cannot fail.
            let _ = instance.set_variable(e.variable, &e.value);
        }
    }

    /// The overrides as RON text, one `"Name": value,` line each, in entry order; floats
    /// are written so that reading them back gives the same `f32`.
    #[must_use]
    pub fn to_ron(&self) -> String {
        let mut out = String::from("{\n");
        for e in &self.entries {
            let _ = writeln!(out, "    \"{}\": {},", e.name, ron_value(&e.value));
        }
        out.push_str("}\n");
        out
    }
}

/// Whether an overrides file can hold a variable of type `ty`.
#[must_use]
pub fn writable(ty: ValueType) -> bool {
    matches!(
        ty,
        ValueType::Float | ValueType::Int | ValueType::Bool | ValueType::Vec3
    )
}

fn ron_float(x: f32) -> String {
    // `{:?}` prints the shortest text that reads back as the same f32, with a `.0` for
    // whole numbers.
    format!("{x:?}")
}

fn ron_value(v: &Value) -> String {
    match v {
        Value::Bool(b) => b.to_string(),
        Value::Int(i) => i.to_string(),
        Value::Float(x) => ron_float(*x),
        Value::Vec3(v) => format!(
            "({}, {}, {})",
            ron_float(v.x),
            ron_float(v.y),
            ron_float(v.z)
        ),
        other => format!("{other:?}"),
    }
}

type EntryError = (Span, String, Option<String>);

fn entry(program: &Program, name: &str, value: &Spanned<Ron>) -> Result<Override, EntryError> {
    let Some(id) = program.variable_id(name) else {
        let hint = strider_graph::suggest(
            name,
            program
                .variables()
                .iter()
                .filter(|v| v.tunable.is_some())
                .map(|v| v.name.as_str()),
        )
        .map(|s| format!("did you mean `{s}`?"));
        return Err((
            Span::default(),
            format!("graph `{}` has no variable `{name}`", program.name()),
            hint,
        ));
    };
    let info = program.variable(id);
    if info.tunable.is_none() {
        return Err((
            Span::default(),
            format!("variable `{name}` is not tunable"),
            Some(format!(
                "only tunable variables can be overridden; declare it with `tunable: true` at {}",
                info.location
            )),
        ));
    }
    let mismatch = || {
        (
            value.span,
            format!("`{name}` is {}, found {}", info.ty, value.value.describe()),
            None,
        )
    };
    let number = |v: &Ron| match *v {
        Ron::Float(x) if x.is_finite() => Some(x as f32),
        Ron::Int(i) => Some(i as f32),
        _ => None,
    };
    let parsed = match (info.ty, &value.value) {
        (ValueType::Bool, Ron::Bool(b)) => Value::Bool(*b),
        (ValueType::Int, Ron::Int(i)) => Value::Int(i32::try_from(*i).map_err(|_| {
            (
                value.span,
                format!("`{name}`: {i} does not fit in a 32-bit Int"),
                None,
            )
        })?),
        (ValueType::Float, v) => Value::Float(number(v).ok_or_else(mismatch)?),
        (ValueType::Vec3, Ron::Tuple(None, items)) if items.len() == 3 => {
            let mut xyz = [0.0; 3];
            for (slot, item) in xyz.iter_mut().zip(items.iter()) {
                *slot = number(&item.value).ok_or_else(mismatch)?;
            }
            Value::Vec3(glam::Vec3::from_array(xyz))
        }
        (ty, _) if !writable(ty) => {
            return Err((
                value.span,
                format!("`{name}` is {ty}: overrides files hold Float, Int, Bool and Vec3 values"),
                None,
            ));
        }
        _ => return Err(mismatch()),
    };
    Ok(Override {
        variable: id,
        name: name.to_string(),
        value: parsed,
    })
}

fn diagnostic(
    path: &Path,
    (line, col): (usize, usize),
    message: String,
    hint: Option<String>,
) -> Diagnostic {
    Diagnostic {
        path: PathBuf::from(path),
        line,
        col,
        message,
        node: None,
        pin: None,
        hint,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::sync::Arc;
    use strider_core::{Bone, Skeleton, Transform};
    use strider_vm::{ProgramBuilder, VariableInfo};

    /// A program with the variables of a graph declaring
    /// `Stride: Float 40 (10..150)`, `Count: Int 3 (1..7)`, `Draw: Bool`, `Offset: Vec3`
    /// (all tunable) and a non-tunable `State: Float`, built by hand (this crate does not
    /// depend on the compiler).
    fn program() -> Program {
        let mut b = ProgramBuilder::new("tuned");
        let vars = [
            (
                "Stride",
                Value::Float(40.0),
                Some((Some(10.0), Some(150.0))),
            ),
            ("Count", Value::Int(3), Some((Some(1.0), Some(7.0)))),
            ("Draw", Value::Bool(true), Some((None, None))),
            ("Offset", Value::Vec3(glam::Vec3::ZERO), Some((None, None))),
            ("State", Value::Float(0.0), None),
        ];
        for (i, (name, default, tunable)) in vars.into_iter().enumerate() {
            let slot = b.constant(&default, "");
            b.variable(VariableInfo {
                name: name.to_string(),
                ty: default.ty(),
                slot,
                default,
                tunable,
                location: format!("tuned.ron:{}:9", 4 + i),
            });
        }
        let entry = b.here();
        b.emit(strider_nodes::Op::End, &[]);
        b.set_construction_entry(entry);
        b.set_forward_entry(entry);
        b.finish()
    }

    fn instance(program: Program) -> Instance {
        let skeleton = Skeleton::new(vec![Bone {
            name: "root".to_string(),
            parent: None,
            rest_local: Transform::IDENTITY,
        }])
        .expect("skeleton");
        Instance::new(Arc::new(program), Arc::new(skeleton)).expect("instance")
    }

    fn errors(text: &str) -> Vec<String> {
        Overrides::parse(Path::new("o.ron"), text, &program())
            .expect_err("should be refused")
            .iter()
            .map(ToString::to_string)
            .collect()
    }

    #[test]
    fn values_of_every_kind_are_read_and_applied() {
        let text = "{ \"Stride\": 55.5, \"Count\": 5, \"Draw\": false, \"Offset\": (1.0, 2, 3.5) }";
        let o = Overrides::parse(Path::new("o.ron"), text, &program()).expect("valid");
        assert_eq!(o.entries.len(), 4);
        let mut inst = instance(program());
        o.apply(&mut inst);
        let p = Arc::clone(inst.program());
        let get = |n: &str| inst.variable(p.variable_id(n).expect("declared"));
        assert_eq!(get("Stride"), Value::Float(55.5));
        assert_eq!(get("Count"), Value::Int(5));
        assert_eq!(get("Draw"), Value::Bool(false));
        assert_eq!(get("Offset"), Value::Vec3(glam::Vec3::new(1.0, 2.0, 3.5)));
    }

    #[test]
    fn an_integer_is_accepted_for_a_float() {
        let o =
            Overrides::parse(Path::new("o.ron"), "{\"Stride\": 60}", &program()).expect("valid");
        assert_eq!(o.entries[0].value, Value::Float(60.0));
    }

    #[test]
    fn written_values_read_back_identically() {
        let mut inst = instance(program());
        let p = Arc::clone(inst.program());
        inst.set_variable(
            p.variable_id("Stride").expect("declared"),
            &Value::Float(0.1 + 0.2),
        )
        .expect("float");
        inst.set_variable(
            p.variable_id("Offset").expect("declared"),
            &Value::Vec3(glam::Vec3::new(-1.25, 1.0e-7, 3.0)),
        )
        .expect("vec3");
        let written = Overrides::from_instance(&inst);
        // Non-tunable `State` is not exported; the four tunables are, in declaration order.
        let names: Vec<&str> = written.entries.iter().map(|e| e.name.as_str()).collect();
        assert_eq!(names, ["Stride", "Count", "Draw", "Offset"]);
        let text = written.to_ron();
        let read = Overrides::parse(Path::new("o.ron"), &text, &program()).expect("reads back");
        assert_eq!(read, written);
    }

    #[test]
    fn problems_name_file_line_and_column() {
        let e = errors("{\n  \"Strid\": 1.0,\n}");
        assert_eq!(e.len(), 1);
        assert!(
            e[0].starts_with("o.ron:2:3: error: graph `tuned` has no variable `Strid`"),
            "{e:?}"
        );
        assert!(e[0].contains("did you mean `Stride`?"), "{e:?}");

        let e = errors("{\"State\": 1.0}");
        assert!(
            e[0].starts_with("o.ron:1:2: error: variable `State` is not tunable"),
            "{e:?}"
        );

        let e = errors("{\"Count\": 2.5, \"Draw\": 1}");
        assert_eq!(e.len(), 2, "every problem is reported: {e:?}");
        assert!(
            e[0].starts_with("o.ron:1:11: error: `Count` is Int, found a float"),
            "{e:?}"
        );
        assert!(
            e[1].starts_with("o.ron:1:24: error: `Draw` is Bool, found an integer"),
            "{e:?}"
        );

        let e = errors("{\"Stride\": 1.0, \"Stride\": 2.0}");
        assert!(
            e[0].contains("1:17: error: `Stride` is given twice"),
            "{e:?}"
        );

        let e = errors("[1, 2]");
        assert!(
            e[0].starts_with("o.ron:1:1: error: expected a map"),
            "{e:?}"
        );

        let e = errors("{\"Stride\": }");
        assert!(
            e[0].starts_with("o.ron:1:"),
            "syntax errors are located: {e:?}"
        );
    }

    #[test]
    fn a_missing_file_is_an_error_not_a_panic() {
        let e = Overrides::load(Path::new("/nonexistent/overrides.ron"), &program())
            .expect_err("missing");
        assert!(e[0].to_string().contains("cannot read the overrides file"));
    }
}
