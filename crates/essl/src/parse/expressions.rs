//! Expressions, by precedence climbing: assignment, `?:`, the binary operators (one table of
//! precedences), unary and postfix operators, calls and constructors, and primary
//! expressions.

use super::types::type_keyword;
use super::{Failed, PResult, Parser};
use crate::ast::*;
use crate::diagnostic::Diagnostic;
use crate::diagnostic_code::Code;
use crate::lex::Punct;
use crate::token::{Kw, Tok};

fn binary_op(p: Punct) -> Option<(BinaryOp, u8)> {
    use BinaryOp::*;
    Some(match p {
        Punct::OrOr => (Or, 1),
        Punct::XorXor => (Xor, 2),
        Punct::AndAnd => (And, 3),
        Punct::Pipe => (BitOr, 4),
        Punct::Caret => (BitXor, 5),
        Punct::Ampersand => (BitAnd, 6),
        Punct::EqualEqual => (Eq, 7),
        Punct::BangEqual => (NotEq, 7),
        Punct::Less => (Less, 8),
        Punct::Greater => (Greater, 8),
        Punct::LessEqual => (LessEq, 8),
        Punct::GreaterEqual => (GreaterEq, 8),
        Punct::LeftShift => (Shl, 9),
        Punct::RightShift => (Shr, 9),
        Punct::Plus => (Add, 10),
        Punct::Minus => (Sub, 10),
        Punct::Star => (Mul, 11),
        Punct::Slash => (Div, 11),
        Punct::Percent => (Mod, 11),
        _ => return None,
    })
}

fn assign_op(p: Punct) -> Option<Option<BinaryOp>> {
    use BinaryOp::*;
    Some(match p {
        Punct::Equal => None,
        Punct::PlusEqual => Some(Add),
        Punct::MinusEqual => Some(Sub),
        Punct::StarEqual => Some(Mul),
        Punct::SlashEqual => Some(Div),
        Punct::PercentEqual => Some(Mod),
        Punct::LeftShiftEqual => Some(Shl),
        Punct::RightShiftEqual => Some(Shr),
        Punct::AmpersandEqual => Some(BitAnd),
        Punct::PipeEqual => Some(BitOr),
        Punct::CaretEqual => Some(BitXor),
        _ => return None,
    })
}

impl Parser<'_> {
    pub(super) fn expr(&mut self) -> PResult<Expr> {
        let mut e = self.assignment()?;
        while self.at(Punct::Comma) {
            self.advance();
            let rhs = self.assignment()?;
            let span = e.span.to(rhs.span);
            e = Expr {
                kind: ExprKind::Comma(Box::new(e), Box::new(rhs)),
                span,
            };
        }
        Ok(e)
    }

    pub(super) fn assignment(&mut self) -> PResult<Expr> {
        self.enter()?;
        let r = self.assignment_inner();
        self.leave();
        r
    }

    fn assignment_inner(&mut self) -> PResult<Expr> {
        let lhs = self.conditional()?;
        if let Tok::P(p) = self.tok() {
            if let Some(op) = assign_op(*p) {
                self.advance();
                let rhs = self.assignment()?;
                let span = lhs.span.to(rhs.span);
                return Ok(Expr {
                    kind: ExprKind::Assign(op, Box::new(lhs), Box::new(rhs)),
                    span,
                });
            }
        }
        Ok(lhs)
    }

    pub(super) fn conditional(&mut self) -> PResult<Expr> {
        let c = self.binary(0)?;
        if self.at(Punct::Question) {
            self.advance();
            let a = self.expr()?;
            self.expect(Punct::Colon)?;
            let b = self.assignment()?;
            let span = c.span.to(b.span);
            return Ok(Expr {
                kind: ExprKind::Ternary(Box::new(c), Box::new(a), Box::new(b)),
                span,
            });
        }
        Ok(c)
    }

    fn binary(&mut self, min_prec: u8) -> PResult<Expr> {
        let mut lhs = self.unary()?;
        // Each operator of a left-associative chain deepens the tree by one level, which
        // counts as nesting (later passes recurse over the tree).
        let mut chain = 0;
        let result = loop {
            let Tok::P(p) = self.tok() else { break Ok(()) };
            let Some((op, prec)) = binary_op(*p) else {
                break Ok(());
            };
            if prec <= min_prec {
                break Ok(());
            }
            self.advance();
            if let Err(f) = self.enter() {
                break Err(f);
            }
            chain += 1;
            let rhs = match self.binary(prec) {
                Ok(r) => r,
                Err(f) => break Err(f),
            };
            let span = lhs.span.to(rhs.span);
            lhs = Expr {
                kind: ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)),
                span,
            };
        };
        for _ in 0..chain {
            self.leave();
        }
        result.map(|_| lhs)
    }

    pub(super) fn unary(&mut self) -> PResult<Expr> {
        let start = self.peek().span;
        let op = match self.peek().tok {
            Tok::P(Punct::Plus) => Some(UnaryOp::Plus),
            Tok::P(Punct::Minus) => Some(UnaryOp::Neg),
            Tok::P(Punct::Bang) => Some(UnaryOp::Not),
            Tok::P(Punct::Tilde) => Some(UnaryOp::BitNot),
            Tok::P(Punct::PlusPlus) => Some(UnaryOp::PreInc),
            Tok::P(Punct::MinusMinus) => Some(UnaryOp::PreDec),
            _ => None,
        };
        if let Some(op) = op {
            self.advance();
            self.enter()?;
            let e = self.unary();
            self.leave();
            let e = e?;
            let span = start.to(e.span);
            return Ok(Expr {
                kind: ExprKind::Unary(op, Box::new(e)),
                span,
            });
        }
        let p = self.primary()?;
        self.postfix(p)
    }

    fn postfix(&mut self, e: Expr) -> PResult<Expr> {
        // Each postfix operator deepens the tree by one level, which counts as nesting.
        let mut applied = 0;
        let r = self.postfix_ops(e, &mut applied);
        for _ in 0..applied {
            self.leave();
        }
        r
    }

    fn postfix_ops(&mut self, mut e: Expr, applied: &mut u32) -> PResult<Expr> {
        loop {
            if matches!(
                self.tok(),
                Tok::P(Punct::LeftBracket | Punct::Dot | Punct::PlusPlus | Punct::MinusMinus)
            ) {
                self.enter()?;
                *applied += 1;
            }
            match self.tok() {
                Tok::P(Punct::LeftBracket) => {
                    let open = self.bump_span();
                    let i = self.expr()?;
                    self.expect_close(Punct::RightBracket, open)?;
                    let span = self.span_from(e.span);
                    e = Expr {
                        kind: ExprKind::Index(Box::new(e), Box::new(i)),
                        span,
                    };
                }
                Tok::P(Punct::Dot) => {
                    self.advance();
                    let name = match self.tok() {
                        // `v.length()` and swizzles/members named like keywords are not a thing,
                        // but give a clear message.
                        Tok::Ident | Tok::Reserved => self.ident("a field name")?,
                        _ => return Err(self.expected("a field name or swizzle after `.`")),
                    };
                    if &*name.name == "length" && self.at(Punct::LeftParen) {
                        let open = self.bump_span();
                        self.expect_close(Punct::RightParen, open)?;
                        let span = self.span_from(e.span);
                        e = Expr {
                            kind: ExprKind::Call(Callee::Length(Box::new(e)), Vec::new()),
                            span,
                        };
                    } else if self.at(Punct::LeftParen) {
                        let d = Diagnostic::error(
                            Code::MethodCall,
                            format!(
                                "`{}` is not a method: GLSL ES 3.00 has only `.length()`",
                                name.name
                            ),
                            name.span,
                        )
                        .with_label("no such method")
                        .with_token(&*name.name);
                        self.report(d);
                        return Err(Failed);
                    } else {
                        let span = e.span.to(name.span);
                        e = Expr {
                            kind: ExprKind::Field(Box::new(e), name),
                            span,
                        };
                    }
                }
                Tok::P(Punct::PlusPlus) => {
                    let s = self.bump_span();
                    let span = e.span.to(s);
                    e = Expr {
                        kind: ExprKind::Unary(UnaryOp::PostInc, Box::new(e)),
                        span,
                    };
                }
                Tok::P(Punct::MinusMinus) => {
                    let s = self.bump_span();
                    let span = e.span.to(s);
                    e = Expr {
                        kind: ExprKind::Unary(UnaryOp::PostDec, Box::new(e)),
                        span,
                    };
                }
                _ => return Ok(e),
            }
        }
    }

    fn call_args(&mut self) -> PResult<Vec<Expr>> {
        let open = self.expect(Punct::LeftParen)?;
        let mut args = Vec::new();
        if self.at_kw(Kw::Void) && matches!(self.peek_at(1).tok, Tok::P(Punct::RightParen)) {
            self.advance();
        } else if !self.at(Punct::RightParen) {
            loop {
                args.push(self.assignment()?);
                if !self.eat(Punct::Comma) {
                    break;
                }
            }
        }
        self.expect_close(Punct::RightParen, open)?;
        Ok(args)
    }

    fn primary(&mut self) -> PResult<Expr> {
        let start = self.peek().span;
        let kind = match self.peek().tok {
            Tok::Int(v, u) => {
                self.advance();
                ExprKind::Int(v, u)
            }
            Tok::Float(f) => {
                self.advance();
                ExprKind::Float(f)
            }
            Tok::Kw(Kw::True) => {
                self.advance();
                ExprKind::Bool(true)
            }
            Tok::Kw(Kw::False) => {
                self.advance();
                ExprKind::Bool(false)
            }
            Tok::P(Punct::LeftParen) => {
                let open = self.bump_span();
                let e = self.expr()?;
                let close = self.expect_close(Punct::RightParen, open)?;
                return Ok(Expr {
                    kind: e.kind,
                    span: open.to(close),
                });
            }
            Tok::Ident if self.is_type_name(&self.peek().text) => {
                let spec = self.type_spec()?;
                if !self.at(Punct::LeftParen) {
                    return Err(self.expected("`(` after a type name (a constructor)"));
                }
                let args = self.call_args()?;
                match spec.array {
                    None => {
                        let TypeName::Named(id) = spec.name else {
                            unreachable!()
                        };
                        ExprKind::Call(Callee::Name(id), args)
                    }
                    Some(_) => ExprKind::Call(Callee::Type(spec), args),
                }
            }
            Tok::Ident | Tok::Reserved => {
                let id = self.ident("an expression")?;
                if self.at(Punct::LeftParen) {
                    let args = self.call_args()?;
                    ExprKind::Call(Callee::Name(id), args)
                } else {
                    ExprKind::Ident(id)
                }
            }
            Tok::Kw(Kw::Struct) => {
                let d = Diagnostic::error(
                    Code::SyntaxError,
                    "a struct cannot be defined inside an expression",
                    start,
                )
                .with_label("not expected here")
                .with_token("struct");
                self.report(d);
                return Err(Failed);
            }
            Tok::Kw(k) if type_keyword(k).is_some() => {
                let spec = self.type_spec()?;
                if !self.at(Punct::LeftParen) {
                    return Err(self.expected("`(` after a type name (a constructor)"));
                }
                let args = self.call_args()?;
                ExprKind::Call(Callee::Type(spec), args)
            }
            _ => return Err(self.expected("an expression")),
        };
        Ok(Expr {
            kind,
            span: self.span_from(start),
        })
    }
}
