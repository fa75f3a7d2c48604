//! Integer expressions of `#if`, `#elif` and `#line`, after macro expansion.
//!
//! Values are 32-bit integers with wrapping arithmetic, as WebGL implementations (ANGLE)
//! evaluate them: `>>` of a negative value shifts in zeros, a shift by less than 0 or more than 31
//! is an error, and so are division by zero and identifiers (undefined macros) — but only where
//! they are evaluated: the right operand of `&&` after a false left one, or of `||` after a true
//! one, may contain anything that parses.

use crate::diagnostic::{Diagnostic, Fix};
use crate::diagnostic_code::Code;
use crate::lex::{PpKind, Punct};
use crate::source::Span;

use super::describe;
use super::expand::Tok;

/// How deeply parentheses and unary operators may nest.
const MAX_DEPTH: u32 = 256;

/// A parser and evaluator of one expression in a directive line.
pub(super) struct ExprParser<'t> {
    /// The expanded tokens of the line, ending with `Eof`.
    toks: &'t [Tok],
    pos: usize,
    /// `#if`, `#elif` or `#line`.
    directive: &'static str,
    /// Integer literals must fit in a signed (`#line`) rather than an unsigned 32-bit integer.
    signed_literals: bool,
    depth: u32,
    /// An error that does not stop parsing (undefined macro, division by zero) was reported.
    pub invalid: bool,
}

/// A binary operator's precedence (higher binds tighter).
fn binary(p: Punct) -> Option<u8> {
    use Punct::*;
    Some(match p {
        OrOr => 1,
        AndAnd => 2,
        Pipe => 3,
        Caret => 4,
        Ampersand => 5,
        EqualEqual | BangEqual => 6,
        Less | Greater | LessEqual | GreaterEqual => 7,
        LeftShift | RightShift => 8,
        Plus | Minus => 9,
        Star | Slash | Percent => 10,
        _ => return None,
    })
}

/// A binary operation to evaluate.
struct Operation<'a> {
    /// The operator.
    op: Punct,
    /// The operator's token (for diagnostics).
    op_tok: &'a Tok,
    /// The left operand's value.
    a: i32,
    /// The right operand's value.
    b: i32,
    /// The right operand's span.
    bspan: Span,
    /// Whether the operation is evaluated: `false` in the skipped operand of `&&` and `||`,
    /// where errors are not reported.
    eval: bool,
}

impl<'t> ExprParser<'t> {
    /// A parser over `toks` (which end with `Eof`).
    pub fn new(toks: &'t [Tok], directive: &'static str, signed_literals: bool) -> Self {
        ExprParser {
            toks,
            pos: 0,
            directive,
            signed_literals,
            depth: 0,
            invalid: false,
        }
    }

    fn peek(&self) -> &'t Tok {
        &self.toks[self.pos.min(self.toks.len() - 1)]
    }

    fn bump(&mut self) -> &'t Tok {
        let t = self.peek();
        if t.t.kind != PpKind::Eof {
            self.pos += 1;
        }
        t
    }

    /// Whether all tokens are read.
    pub fn at_end(&self) -> bool {
        self.peek().t.kind == PpKind::Eof
    }

    /// The token after the expression.
    pub fn current(&self) -> &'t Tok {
        self.peek()
    }

    /// Parses and evaluates one expression; `None` after a syntax error (reported).
    pub fn parse(&mut self, diags: &mut Vec<Diagnostic>) -> Option<i32> {
        if self.at_end() {
            let t = self.peek();
            diags.push(
                Diagnostic::error(
                    Code::MissingExpression,
                    format!("expected an expression after `{}`", self.directive),
                    t.t.span,
                )
                .with_label("expected an expression")
                .with_help("write an integer expression, such as `defined(NAME)` or `NAME > 1`")
                .with_token(&*t.t.text),
            );
            return None;
        }
        self.binary(diags, 0, true).map(|(v, _)| v)
    }

    fn binary(&mut self, diags: &mut Vec<Diagnostic>, min: u8, eval: bool) -> Option<(i32, Span)> {
        let (mut lhs, mut span) = self.unary(diags, eval)?;
        loop {
            let op_tok = self.peek();
            let PpKind::Punct(op) = op_tok.t.kind else {
                break;
            };
            let Some(prec) = binary(op) else { break };
            if prec < min {
                break;
            }
            self.bump();
            let (rhs, rspan) = match op {
                Punct::AndAnd => self.binary(diags, prec + 1, eval && lhs != 0)?,
                Punct::OrOr => self.binary(diags, prec + 1, eval && lhs == 0)?,
                _ => self.binary(diags, prec + 1, eval)?,
            };
            let operation = Operation {
                op,
                op_tok,
                a: lhs,
                b: rhs,
                bspan: rspan,
                eval,
            };
            lhs = self.apply(diags, operation);
            span = span.to(rspan);
        }
        Some((lhs, span))
    }

    /// The value of a binary operation; a shift out of range or a division by zero is
    /// reported (where evaluated) and gives 0.
    fn apply(&mut self, diags: &mut Vec<Diagnostic>, operation: Operation<'_>) -> i32 {
        use Punct::*;
        let Operation {
            op,
            op_tok,
            a,
            b,
            bspan,
            eval,
        } = operation;
        match op {
            OrOr => (a != 0 || b != 0) as i32,
            AndAnd => (a != 0 && b != 0) as i32,
            Pipe => a | b,
            Caret => a ^ b,
            Ampersand => a & b,
            EqualEqual => (a == b) as i32,
            BangEqual => (a != b) as i32,
            Less => (a < b) as i32,
            Greater => (a > b) as i32,
            LessEqual => (a <= b) as i32,
            GreaterEqual => (a >= b) as i32,
            LeftShift | RightShift => {
                if !(0..=31).contains(&b) {
                    if eval {
                        self.invalid = true;
                        diags.push(
                            Diagnostic::error(
                                Code::InvalidShift,
                                format!(
                                    "shift by {b} in `{}`: the amount must be 0 to 31",
                                    self.directive
                                ),
                                bspan,
                            )
                            .with_label(format!("this is {b}"))
                            .with_secondary(op_tok.t.span, "")
                            .with_help("shift by 0 to 31 bits")
                            .with_token(&*op_tok.t.text),
                        );
                    }
                    0
                } else if op == LeftShift {
                    ((a as u32) << b) as i32
                } else {
                    ((a as u32) >> b) as i32
                }
            }
            Plus => a.wrapping_add(b),
            Minus => a.wrapping_sub(b),
            Star => a.wrapping_mul(b),
            Slash | Percent => {
                if b == 0 {
                    if eval {
                        self.invalid = true;
                        diags.push(
                            Diagnostic::error(
                                Code::DivisionByZero,
                                format!(
                                    "{} by zero in `{}`",
                                    if op == Slash { "division" } else { "remainder" },
                                    self.directive
                                ),
                                bspan,
                            )
                            .with_label("this is 0")
                            .with_secondary(op_tok.t.span, "")
                            .with_help("check the macros that make the divisor 0")
                            .with_token(&*op_tok.t.text),
                        );
                    }
                    0
                } else if a == i32::MIN && b == -1 {
                    if op == Slash {
                        i32::MAX
                    } else {
                        0
                    }
                } else if op == Slash {
                    a / b
                } else {
                    a % b
                }
            }
            _ => 0,
        }
    }

    fn unary(&mut self, diags: &mut Vec<Diagnostic>, eval: bool) -> Option<(i32, Span)> {
        if self.depth >= MAX_DEPTH {
            self.too_deep(diags);
            return None;
        }
        self.depth += 1;
        let r = self.unary_inner(diags, eval);
        self.depth -= 1;
        r
    }

    #[cold]
    #[inline(never)]
    fn too_deep(&self, diags: &mut Vec<Diagnostic>) {
        let t = self.peek();
        diags.push(
            Diagnostic::error(
                Code::ExpressionTooDeep,
                format!(
                    "`{}` expression nested more than {MAX_DEPTH} levels deep",
                    self.directive
                ),
                t.t.span,
            )
            .with_label("too deep here")
            .with_help("simplify the expression")
            .with_token(&*t.t.text),
        );
    }

    fn unary_inner(&mut self, diags: &mut Vec<Diagnostic>, eval: bool) -> Option<(i32, Span)> {
        let t = self.bump();
        let span = t.t.span;
        match t.t.kind {
            PpKind::Number => Some((self.literal(diags, t)?, span)),
            PpKind::Ident => {
                if eval {
                    self.invalid = true;
                    self.undefined(diags, t);
                }
                Some((0, span))
            }
            PpKind::Punct(Punct::LeftParen) => {
                let (v, _) = self.binary(diags, 0, eval)?;
                let close = self.peek();
                if !close.t.is(Punct::RightParen) {
                    self.unclosed(diags, t, close);
                    return None;
                }
                self.bump();
                Some((v, span.to(close.t.span)))
            }
            PpKind::Punct(p @ (Punct::Plus | Punct::Minus | Punct::Tilde | Punct::Bang)) => {
                let (v, s) = self.unary(diags, eval)?;
                let v = match p {
                    Punct::Plus => v,
                    Punct::Minus => v.wrapping_neg(),
                    Punct::Tilde => !v,
                    _ => (v == 0) as i32,
                };
                Some((v, span.to(s)))
            }
            _ => {
                self.unexpected(diags, t);
                None
            }
        }
    }

    #[cold]
    #[inline(never)]
    fn undefined(&self, diags: &mut Vec<Diagnostic>, t: &Tok) {
        let name = &*t.t.text;
        let span = t.t.span;
        let mut d = Diagnostic::error(
            Code::UndefinedMacroInIf,
            format!("`{name}` is not a defined macro"),
            span,
        )
        .with_label(format!(
            "an undefined name in `{}` is an error in GLSL ES 3.00, not 0",
            self.directive
        ))
        .with_token(name);
        if self.directive == "#line" {
            d = d.with_help("`#line` takes integer expressions");
        } else if t.t.from_macro {
            d = d.with_help(format!(
                "a macro in this line expands to `{name}`: test it with `defined({name})` or define it"
            ));
        } else {
            d = d
                .with_help(format!(
                    "to test whether it is defined, write `defined({name})`"
                ))
                .with_fix(Fix::suggested(
                    format!("write `defined({name})`"),
                    span,
                    format!("defined({name})"),
                ));
        }
        diags.push(d);
    }

    #[cold]
    #[inline(never)]
    fn unclosed(&self, diags: &mut Vec<Diagnostic>, open: &Tok, close: &Tok) {
        diags.push(
            Diagnostic::error(
                Code::InvalidExpression,
                format!(
                    "expected `)` in `{}` expression, found {}",
                    self.directive,
                    describe(&close.t)
                ),
                close.t.span,
            )
            .with_label("expected `)`")
            .with_secondary(open.t.span, "to close this `(`")
            .with_help("`#if` and `#line` take integer expressions with C's operators")
            .with_token(&*close.t.text),
        );
    }

    #[cold]
    #[inline(never)]
    fn unexpected(&self, diags: &mut Vec<Diagnostic>, t: &Tok) {
        let span = t.t.span;
        let d = match t.t.kind {
            PpKind::Invalid(c) => Diagnostic::error(
                Code::InvalidCharacter,
                format!(
                    "invalid character {} in `{}` expression",
                    super::char_display(c),
                    self.directive
                ),
                span,
            )
            .with_label("not part of GLSL ES's character set")
            .with_token(super::char_token(c)),
            PpKind::Eof => Diagnostic::error(
                Code::InvalidExpression,
                format!("`{}` expression ends too early", self.directive),
                span,
            )
            .with_label("expected an operand here")
            .with_help("`#if` and `#line` take integer expressions with C's operators")
            .with_token(""),
            PpKind::Punct(p @ (Punct::PlusPlus | Punct::MinusMinus)) => {
                let one = &p.as_str()[..1];
                Diagnostic::error(
                    Code::InvalidExpression,
                    format!(
                        "`{}` is not an operator in `{}` expressions",
                        p.as_str(),
                        self.directive
                    ),
                    span,
                )
                .with_label("expected a number, a macro, `defined`, `(` or a unary operator")
                .with_fix(Fix::suggested(
                    format!("separate the signs: `{one} {one}`"),
                    span,
                    format!("{one} {one}"),
                ))
                .with_help("`#if` and `#line` take integer expressions with C's operators")
                .with_token(&*t.t.text)
            }
            _ => Diagnostic::error(
                Code::InvalidExpression,
                format!(
                    "unexpected {} in `{}` expression",
                    describe(&t.t),
                    self.directive
                ),
                span,
            )
            .with_label("expected a number, a macro, `defined`, `(` or a unary operator")
            .with_help("`#if` and `#line` take integer expressions with C's operators")
            .with_token(&*t.t.text),
        };
        diags.push(d);
    }

    /// The value of an integer literal (decimal, octal or hexadecimal, optional `u`).
    fn literal(&mut self, diags: &mut Vec<Diagnostic>, t: &Tok) -> Option<i32> {
        let text = &*t.t.text;
        let body = text.strip_suffix(['u', 'U']).unwrap_or(text);
        let parsed = if let Some(hex) = body.strip_prefix("0x").or_else(|| body.strip_prefix("0X"))
        {
            if !hex.is_empty() && hex.bytes().all(|b| b.is_ascii_hexdigit()) {
                Some(u64::from_str_radix(hex, 16).unwrap_or(u64::MAX))
            } else {
                None
            }
        } else if body.len() > 1 && body.starts_with('0') {
            if body.bytes().all(|b| (b'0'..=b'7').contains(&b)) {
                Some(u64::from_str_radix(body, 8).unwrap_or(u64::MAX))
            } else {
                None
            }
        } else if !body.is_empty() && body.bytes().all(|b| b.is_ascii_digit()) {
            Some(body.parse::<u64>().unwrap_or(u64::MAX))
        } else {
            None
        };
        let Some(v) = parsed else {
            let float = text.contains(['.', 'e', 'E']) && !text.starts_with("0x");
            diags.push(
                Diagnostic::error(
                    Code::NonIntegerInExpression,
                    if float {
                        format!(
                            "floating-point number `{text}` in `{}`: only integers are allowed",
                            self.directive
                        )
                    } else {
                        format!("`{text}` is not a valid integer in `{}`", self.directive)
                    },
                    t.t.span,
                )
                .with_label("not an integer")
                .with_help(
                    "use an integer (decimal, octal with a leading 0, or hexadecimal with 0x)",
                )
                .with_token(text),
            );
            return None;
        };
        let limit = if self.signed_literals {
            i32::MAX as u64
        } else {
            u32::MAX as u64
        };
        if v > limit {
            self.invalid = true;
            diags.push(
                Diagnostic::error(
                    Code::IntegerOverflow,
                    format!("integer `{text}` is too large for `{}`", self.directive),
                    t.t.span,
                )
                .with_label(format!("larger than {limit}"))
                .with_help("use a smaller number")
                .with_token(text),
            );
            return Some(0);
        }
        Some(v as u32 as i32)
    }
}
