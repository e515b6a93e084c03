//! What every command that runs a graph shares: loading and compiling, instantiating with a
//! readable missing-bone error, and `--set NAME=VALUE` variable assignments.

use crate::check::guard;
use crate::{output, value};
use anyhow::{Context as _, anyhow, bail};
use std::fmt::Write as _;
use std::path::Path;
use std::sync::Arc;
use strider_core::WorldQuery;
use strider_graph::{Diagnostic, SkeletonFile};
use strider_nodes::Value;
use strider_vm::{Instance, InstantiateError, Program, VariableId};

/// Instantiates `program` on `skeleton` (read from `path`); a skeleton that lacks bones the
/// graph names is reported once per reference, then as one error naming them all.
pub(crate) fn instantiate(
    program: &Arc<Program>,
    skeleton: &SkeletonFile,
    path: &Path,
) -> anyhow::Result<Instance> {
    match Instance::new(Arc::clone(program), skeleton.skeleton.clone()) {
        Ok(instance) => Ok(instance),
        Err(InstantiateError::MissingBones { mut missing, .. }) => {
            // A pure node emitted in front of several exec steps reports the same reference
            // once per step: show each reference once.
            let mut seen = std::collections::HashSet::new();
            missing.retain(|m| seen.insert((m.name.clone(), m.location.clone())));
            let mut names: Vec<String> = missing.iter().map(|m| m.name.clone()).collect();
            names.sort_unstable();
            names.dedup();
            let label = skeleton_label(skeleton, path);
            // Re-labelled with the skeleton's own name: the VM only knows it as "skeleton".
            let e = InstantiateError::MissingBones {
                skeleton: label.clone(),
                missing,
            };
            output::error_line(&e.to_string());
            bail!(
                "graph `{}` names {} that skeleton `{label}` ({}) lacks: {}",
                program.name(),
                if names.len() == 1 {
                    "a bone".to_string()
                } else {
                    format!("{} bones", names.len())
                },
                path.display(),
                names.join(", ")
            );
        }
    }
}

/// Loads the skeleton and compiles the graph, reporting the diagnostics of both.
pub(crate) fn load(graph: &Path, skeleton: &Path) -> anyhow::Result<(Program, SkeletonFile)> {
    let skel = guard(skeleton, || strider_graph::load_skeleton(skeleton));
    let program = guard(graph, || strider_compiler::compile_file(graph));
    let mut failures = Vec::new();
    let mut report = |path: &Path, d: &[Diagnostic]| {
        output::print_diagnostics(d);
        failures.push(format!(
            "{} in {}",
            output::problems(d.len().max(1)),
            path.display()
        ));
    };
    match (program, skel) {
        (Ok(p), Ok(s)) => Ok((p, s)),
        (p, s) => {
            if let Err(d) = &p {
                report(graph, d);
            }
            if let Err(d) = &s {
                report(skeleton, d);
            }
            Err(anyhow!("{}", failures.join(", ")))
        }
    }
}

pub(crate) fn skeleton_label(skeleton: &SkeletonFile, path: &Path) -> String {
    if skeleton.name.is_empty() {
        path.display().to_string()
    } else {
        skeleton.name.clone()
    }
}

/// One `--set`, resolved against the program.
#[derive(Debug)]
pub(crate) struct Assignment {
    id: VariableId,
    value: Value,
    tunable: bool,
}

/// The values of an overrides file (`--overrides FILE`, see
/// [`strider_host::overrides`]) followed by every `--set`, resolved before anything runs:
/// `--set` wins over the file for a variable both give.
///
/// # Errors
/// Every problem of the overrides file is printed (`path:line:col: error: ...`) before the
/// error; as [`parse_assignments`] for `--set`.
pub(crate) fn resolve_assignments(
    program: &Program,
    overrides: Option<&Path>,
    sets: &[String],
) -> anyhow::Result<Vec<Assignment>> {
    let mut out = Vec::new();
    if let Some(path) = overrides {
        match strider_host::overrides::Overrides::load(path, program) {
            Ok(file) => out.extend(file.entries.into_iter().map(|e| Assignment {
                id: e.variable,
                value: e.value,
                tunable: true,
            })),
            Err(d) => {
                output::print_diagnostics(&d);
                bail!(
                    "{} in the overrides file {}",
                    output::problems(d.len().max(1)),
                    path.display()
                );
            }
        }
    }
    out.extend(parse_assignments(program, sets)?);
    Ok(out)
}

/// Resolves and parses every `--set` before anything runs.
pub(crate) fn parse_assignments(
    program: &Program,
    sets: &[String],
) -> anyhow::Result<Vec<Assignment>> {
    let mut out = Vec::with_capacity(sets.len());
    for text in sets {
        let (name, raw) = value::split_assignment(text)?;
        let id = program
            .variable_id(name)
            .ok_or_else(|| anyhow!("{}", unknown_variable(program, name)))?;
        let info = program.variable(id);
        let value = value::parse_value(info.ty, raw)
            .with_context(|| format!("`--set {text}`: `{name}` is a {}", info.ty))?;
        if let Some((min, max)) = info.tunable {
            let x = match value {
                Value::Float(x) => Some(x),
                Value::Int(i) => Some(i as f32),
                _ => None,
            };
            if let Some(x) = x
                && (min.is_some_and(|m| x < m) || max.is_some_and(|m| x > m))
            {
                output::error_line(&format!(
                    "warning: `{name}` = {raw} is outside its tunable range {}; setting it anyway",
                    range(min, max)
                ));
            }
        } else {
            output::error_line(&format!(
                "warning: `{name}` is not a tunable variable of graph `{}`; setting it anyway \
                 (after the construction event)",
                program.name()
            ));
        }
        out.push(Assignment {
            id,
            value,
            tunable: info.tunable.is_some(),
        });
    }
    Ok(out)
}

/// `unknown variable ...`, with a suggestion and the graph's tunable variables.
fn unknown_variable(program: &Program, name: &str) -> String {
    let mut msg = format!("unknown variable `{name}` in graph `{}`", program.name());
    if let Some(s) =
        strider_graph::suggest(name, program.variables().iter().map(|v| v.name.as_str()))
    {
        let _ = write!(msg, " (did you mean `{s}`?)");
    }
    let tunables: Vec<String> = program
        .variables()
        .iter()
        .filter_map(|v| {
            v.tunable
                .map(|(min, max)| format!("{} ({}, {})", v.name, v.ty, range(min, max)))
        })
        .collect();
    if tunables.is_empty() {
        msg.push_str("; the graph has no tunable variables");
    } else {
        let _ = write!(msg, "; tunable variables: {}", tunables.join(", "));
    }
    msg
}

/// `0..20`, `..4`, `0..`, `any value`.
fn range(min: Option<f32>, max: Option<f32>) -> String {
    match (min, max) {
        (None, None) => "any value".to_string(),
        (min, max) => format!(
            "{}..{}",
            min.map(|m| m.to_string()).unwrap_or_default(),
            max.map(|m| m.to_string()).unwrap_or_default()
        ),
    }
}

/// Sets the variables: tunables first, then `construction` re-runs so that what it derives
/// from them is current (`rebind` keeps tunables and resets the rest), then the others.
pub(crate) fn apply_assignments(
    instance: &mut Instance,
    skeleton: &SkeletonFile,
    assignments: &[Assignment],
    world: &dyn WorldQuery,
) -> anyhow::Result<()> {
    let set = |instance: &mut Instance, a: &Assignment| {
        instance
            .set_variable(a.id, &a.value)
            .map_err(|e| anyhow!("--set: {e}"))
    };
    let mut any_tunable = false;
    for a in assignments.iter().filter(|a| a.tunable) {
        set(instance, a)?;
        any_tunable = true;
    }
    if any_tunable {
        instance
            .rebind(skeleton.skeleton.clone(), world)
            .map_err(|e| anyhow!("{e}"))?;
    }
    for a in assignments.iter().filter(|a| !a.tunable) {
        set(instance, a)?;
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use std::path::PathBuf;

    fn repo_file(path: &str) -> PathBuf {
        Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("../..")
            .join(path)
    }

    #[test]
    fn tunables_set_before_construction_and_state_after() {
        let (program, skeleton) = load(
            &repo_file("graphs/examples/feet_finder.ron"),
            &repo_file("graphs/skeletons/mannequin.ron"),
        )
        .unwrap();
        let program = Arc::new(program);
        let mut instance = Instance::new(Arc::clone(&program), skeleton.skeleton.clone()).unwrap();
        let sets = ["AnkleHeight=0".to_string()];
        let assignments = parse_assignments(&program, &sets).unwrap();
        apply_assignments(
            &mut instance,
            &skeleton,
            &assignments,
            &strider_core::EmptyWorld,
        )
        .unwrap();
        let id = program.variable_id("AnkleHeight").unwrap();
        assert_eq!(instance.variable(id), Value::Float(0.0));
        // Construction ran again with the new ankle height: the soles are the ankles.
        let soles = program.variable_id("LockedFootLocationArray").unwrap();
        let Value::Array(_, soles) = instance.variable(soles) else {
            panic!()
        };
        let foot_l = skeleton.skeleton.find("foot_l").unwrap();
        let Value::Transform(sole) = &soles[0] else {
            panic!()
        };
        let ankle = skeleton.skeleton.rest_global(foot_l).translation;
        assert!((sole.translation - ankle).length() < 1e-4, "{sole:?}");

        assert!(parse_assignments(&program, &["Nope=1".to_string()]).is_err());
        assert!(parse_assignments(&program, &["AnkleHeight=x".to_string()]).is_err());
        assert!(parse_assignments(&program, &["FootArray=1".to_string()]).is_err());
    }

    #[test]
    fn ranges_read_naturally() {
        assert_eq!(range(Some(0.0), Some(20.0)), "0..20");
        assert_eq!(range(None, Some(4.5)), "..4.5");
        assert_eq!(range(Some(1.0), None), "1..");
        assert_eq!(range(None, None), "any value");
    }
}
