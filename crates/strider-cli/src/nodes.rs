//! `strider nodes [--markdown]`: the built-in node table.

use crate::output;
use std::fmt::Write as _;
use std::process::ExitCode;
use strider_nodes::{Effect, NodeSpec, registry};

/// Arguments of `strider nodes`.
#[derive(Debug, clap::Args)]
#[command(
    about = "List the built-in nodes",
    long_about = "List the built-in nodes: one line per node with its category, whether it is \
        pure (pulled by data links) or mutating (placed in an exec list), and the first \
        sentence of its documentation.\n\n\
        With --markdown, print the full node reference (pins, types, defaults, units, \
        examples) as Markdown; `docs/nodes.md` is this output:\n  \
        strider nodes --markdown > docs/nodes.md"
)]
pub(crate) struct NodesArgs {
    /// Print the full node reference as Markdown instead of the compact table.
    #[arg(long)]
    pub markdown: bool,
}

/// Runs `strider nodes`.
pub(crate) fn run(args: &NodesArgs) -> anyhow::Result<ExitCode> {
    let text = if args.markdown {
        registry().markdown()
    } else {
        table(registry().nodes())
    };
    output::print_stdout(&text)?;
    Ok(ExitCode::SUCCESS)
}

/// `Name  (category, pure|mutating)  first sentence`, columns aligned.
fn table(nodes: &[NodeSpec]) -> String {
    let kind = |n: &NodeSpec| {
        let effect = match n.effect {
            Effect::Pure => "pure",
            Effect::Mutating => "mutating",
        };
        format!("({}, {effect})", n.category)
    };
    let name_w = nodes
        .iter()
        .map(|n| n.name.chars().count())
        .max()
        .unwrap_or(0);
    let kind_w = nodes
        .iter()
        .map(|n| kind(n).chars().count())
        .max()
        .unwrap_or(0);
    let mut out = String::new();
    for n in nodes {
        let _ = writeln!(
            out,
            "{:name_w$}  {:kind_w$}  {}",
            n.name,
            kind(n),
            first_sentence(n.doc)
        );
    }
    out
}

/// The doc's first sentence, on one line: up to the first `.` that is followed by a space
/// or the end, outside backticks and not part of `e.g.` / `i.e.`.
fn first_sentence(doc: &str) -> String {
    let doc = doc.split_whitespace().collect::<Vec<_>>().join(" ");
    let mut in_code = false;
    for (i, c) in doc.char_indices() {
        match c {
            '`' => in_code = !in_code,
            '.' if !in_code => {
                let after = &doc[i + 1..];
                let before = &doc[..i];
                let abbreviation = ["e.g", "i.e", "etc", "vs"]
                    .iter()
                    .any(|a| before.ends_with(a));
                if (after.is_empty() || after.starts_with(' ')) && !abbreviation {
                    return doc[..=i].to_string();
                }
            }
            _ => {}
        }
    }
    doc
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn first_sentences() {
        assert_eq!(
            first_sentence("Sine of an angle in degrees."),
            "Sine of an angle in degrees."
        );
        assert_eq!(
            first_sentence("`value` limited to `[min, max]`. If `min > max` the result is `max`."),
            "`value` limited to `[min, max]`."
        );
        assert_eq!(
            first_sentence("Uses `a.b` and\n   e.g. this. Then."),
            "Uses `a.b` and e.g. this."
        );
        assert_eq!(first_sentence("No period"), "No period");
        assert_eq!(
            first_sentence("Version 1.5 is here. Next"),
            "Version 1.5 is here."
        );
    }

    #[test]
    fn one_aligned_line_per_node() {
        let nodes = registry().nodes();
        let text = table(nodes);
        assert_eq!(text.lines().count(), nodes.len());
        for (line, node) in text.lines().zip(nodes) {
            assert!(line.starts_with(node.name), "{line}");
            assert!(
                line.contains("pure)") || line.contains("mutating)"),
                "{line}"
            );
        }
    }
}
