//! Text that breaks where it is too long: a call or constructor whose line would pass the
//! width puts one argument on a line, as rustfmt and a person do.

/// The width lines are kept to, where an argument list can break.
pub(crate) const WIDTH: usize = 100;

/// A piece of text.
#[derive(Clone, Debug)]
pub(crate) enum Doc {
    /// Text that never breaks.
    Text(String),
    /// Pieces one after the other.
    Cat(Vec<Doc>),
    /// `head(arg, arg)`: one argument a line (each followed by a comma) when too long.
    List { head: String, args: Vec<Doc> },
    /// `a * b * c`: a new line before an operator where the next operand would pass the
    /// width.
    Ops {
        first: Box<Doc>,
        rest: Vec<(String, Doc)>,
    },
}

impl Doc {
    /// Text.
    pub(crate) fn text(s: impl Into<String>) -> Doc {
        Doc::Text(s.into())
    }

    /// The length on one line.
    pub(crate) fn flat_len(&self) -> usize {
        match self {
            Doc::Text(s) => s.len(),
            Doc::Cat(parts) => parts.iter().map(Doc::flat_len).sum(),
            Doc::List { head, args } => {
                head.len()
                    + 2
                    + args.iter().map(Doc::flat_len).sum::<usize>()
                    + 2 * args.len().saturating_sub(1)
            }
            Doc::Ops { first, rest } => {
                first.flat_len()
                    + rest
                        .iter()
                        .map(|(o, d)| o.len() + 2 + d.flat_len())
                        .sum::<usize>()
            }
        }
    }

    /// On one line.
    pub(crate) fn flat(&self) -> String {
        let mut out = String::new();
        self.write_flat(&mut out);
        out
    }

    fn write_flat(&self, out: &mut String) {
        match self {
            Doc::Text(s) => out.push_str(s),
            Doc::Cat(parts) => parts.iter().for_each(|p| p.write_flat(out)),
            Doc::List { head, args } => {
                out.push_str(head);
                out.push('(');
                for (i, a) in args.iter().enumerate() {
                    if i > 0 {
                        out.push_str(", ");
                    }
                    a.write_flat(out);
                }
                out.push(')');
            }
            Doc::Ops { first, rest } => {
                first.write_flat(out);
                for (o, d) in rest {
                    out.push_str(&format!(" {o} "));
                    d.write_flat(out);
                }
            }
        }
    }

    /// The lines of the text, the first starting at column `column` of a line indented by
    /// `indent` spaces, the others indented by `indent` (plus their nesting) themselves.
    pub(crate) fn lines(&self, indent: usize, column: usize, tail: usize) -> Vec<String> {
        let mut lines = vec![String::new()];
        self.render(indent, column, tail, true, &mut lines);
        lines
    }

    /// Only a list that nothing but plain text precedes in its statement breaks: a person
    /// breaks `return Output(…)` one argument a line, not a call inside an arithmetic line.
    fn render(
        &self,
        indent: usize,
        column: usize,
        tail: usize,
        breakable: bool,
        lines: &mut Vec<String>,
    ) {
        let col = |lines: &Vec<String>, first: usize| {
            let last = lines.last().map_or(0, |l| l.len());
            if lines.len() == 1 {
                first + last
            } else {
                last
            }
        };
        match self {
            Doc::Text(s) => lines.last_mut().expect("a line").push_str(s),
            Doc::Cat(parts) => {
                for (i, p) in parts.iter().enumerate() {
                    // What follows this part on its line, if it does not break.
                    let rest: usize = parts[i + 1..].iter().map(Doc::flat_len).sum();
                    let plain = parts[..i].iter().all(|q| matches!(q, Doc::Text(_)));
                    p.render(indent, column, rest + tail, breakable && plain, lines);
                }
            }
            Doc::List { head, args } => {
                let start = col(lines, column);
                if !breakable || start + self.flat_len() + tail <= WIDTH || args.is_empty() {
                    self.write_flat(lines.last_mut().expect("a line"));
                    return;
                }
                lines.last_mut().expect("a line").push_str(head);
                lines.last_mut().expect("a line").push('(');
                let inner = indent + 4;
                for a in args {
                    lines.push(" ".repeat(inner));
                    a.render(inner, 0, 1, true, lines);
                    lines.last_mut().expect("a line").push(',');
                }
                lines.push(" ".repeat(indent));
                lines.last_mut().expect("a line").push(')');
            }
            Doc::Ops { first, rest } => {
                let start = col(lines, column);
                if !breakable || start + self.flat_len() + tail <= WIDTH {
                    self.write_flat(lines.last_mut().expect("a line"));
                    return;
                }
                first.write_flat(lines.last_mut().expect("a line"));
                for (k, (o, d)) in rest.iter().enumerate() {
                    let after = if k + 1 == rest.len() { tail } else { 0 };
                    let width = o.len() + 2 + d.flat_len() + after;
                    if col(lines, column) + width > WIDTH {
                        lines.push(" ".repeat(indent + 4));
                        lines.last_mut().expect("a line").push_str(&format!("{o} "));
                    } else {
                        lines
                            .last_mut()
                            .expect("a line")
                            .push_str(&format!(" {o} "));
                    }
                    d.write_flat(lines.last_mut().expect("a line"));
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn breaks_only_what_is_too_long() {
        let short = Doc::List {
            head: "vec3f".into(),
            args: vec![Doc::text("a"), Doc::text("b"), Doc::text("c")],
        };
        assert_eq!(short.lines(4, 4, 1), ["vec3f(a, b, c)"]);
        let long = Doc::Cat(vec![
            Doc::text("return "),
            Doc::List {
                head: "VertexOutput".into(),
                args: vec![Doc::text("x".repeat(60)), Doc::text("y".repeat(40))],
            },
        ]);
        let lines = long.lines(4, 4, 1);
        assert_eq!(lines[0], "return VertexOutput(");
        assert_eq!(lines[1], format!("        {},", "x".repeat(60)));
        assert_eq!(lines[3], "    )");
    }
}
