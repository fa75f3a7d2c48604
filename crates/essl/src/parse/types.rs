//! Types and qualifiers: the type keywords, type specifiers (with their array sizes),
//! struct definitions and the qualifier list before a type.

use crate::diagnostic_code::Code;
use std::sync::Arc;

use super::{Failed, PResult, Parser};
use crate::ast::*;
use crate::diagnostic::{Diagnostic, Fix};
use crate::lex::Punct;
use crate::source::Span;
use crate::token::{Kw, Tok};
use crate::types::{Precision, SamplerType, ScalarKind};
use crate::Stage;

pub(super) fn type_keyword(kw: Kw) -> Option<TypeName> {
    use ScalarKind::*;
    Some(match kw {
        Kw::Void => TypeName::Void,
        Kw::Float => TypeName::Scalar(Float),
        Kw::Int => TypeName::Scalar(Int),
        Kw::Uint => TypeName::Scalar(Uint),
        Kw::Bool => TypeName::Scalar(Bool),
        Kw::Vec2 => TypeName::Vector(Float, 2),
        Kw::Vec3 => TypeName::Vector(Float, 3),
        Kw::Vec4 => TypeName::Vector(Float, 4),
        Kw::Ivec2 => TypeName::Vector(Int, 2),
        Kw::Ivec3 => TypeName::Vector(Int, 3),
        Kw::Ivec4 => TypeName::Vector(Int, 4),
        Kw::Uvec2 => TypeName::Vector(Uint, 2),
        Kw::Uvec3 => TypeName::Vector(Uint, 3),
        Kw::Uvec4 => TypeName::Vector(Uint, 4),
        Kw::Bvec2 => TypeName::Vector(Bool, 2),
        Kw::Bvec3 => TypeName::Vector(Bool, 3),
        Kw::Bvec4 => TypeName::Vector(Bool, 4),
        Kw::Mat2 | Kw::Mat2x2 => TypeName::Matrix { cols: 2, rows: 2 },
        Kw::Mat3 | Kw::Mat3x3 => TypeName::Matrix { cols: 3, rows: 3 },
        Kw::Mat4 | Kw::Mat4x4 => TypeName::Matrix { cols: 4, rows: 4 },
        Kw::Mat2x3 => TypeName::Matrix { cols: 2, rows: 3 },
        Kw::Mat2x4 => TypeName::Matrix { cols: 2, rows: 4 },
        Kw::Mat3x2 => TypeName::Matrix { cols: 3, rows: 2 },
        Kw::Mat3x4 => TypeName::Matrix { cols: 3, rows: 4 },
        Kw::Mat4x2 => TypeName::Matrix { cols: 4, rows: 2 },
        Kw::Mat4x3 => TypeName::Matrix { cols: 4, rows: 3 },
        _ => return SamplerType::from_name(kw.as_str()).map(TypeName::Sampler),
    })
}

pub(super) fn is_qualifier_kw(kw: Kw) -> bool {
    matches!(
        kw,
        Kw::Const
            | Kw::In
            | Kw::Out
            | Kw::Inout
            | Kw::Uniform
            | Kw::Centroid
            | Kw::Flat
            | Kw::Smooth
            | Kw::Invariant
            | Kw::Lowp
            | Kw::Mediump
            | Kw::Highp
            | Kw::Layout
            | Kw::Attribute
            | Kw::Varying
    )
}

impl Parser<'_> {
    /// Parses qualifiers in any order (the checker enforces ES 3.00's order).
    pub(super) fn qualifiers(&mut self) -> PResult<Vec<(Qualifier, Span)>> {
        let mut out = Vec::new();
        loop {
            let span = self.peek().span;
            let q = match self.peek().tok {
                Tok::Kw(Kw::Const) => Qualifier::Storage(Storage::Const),
                Tok::Kw(Kw::In) => Qualifier::Storage(Storage::In),
                Tok::Kw(Kw::Out) => Qualifier::Storage(Storage::Out),
                Tok::Kw(Kw::Inout) => Qualifier::Storage(Storage::Inout),
                Tok::Kw(Kw::Uniform) => Qualifier::Storage(Storage::Uniform),
                Tok::Kw(Kw::Attribute) => Qualifier::Storage(Storage::Attribute),
                Tok::Kw(Kw::Varying) => Qualifier::Storage(Storage::Varying),
                Tok::Kw(Kw::Centroid) => Qualifier::Centroid,
                Tok::Kw(Kw::Flat) => Qualifier::Interpolation(Interpolation::Flat),
                Tok::Kw(Kw::Smooth) => Qualifier::Interpolation(Interpolation::Smooth),
                Tok::Kw(Kw::Invariant) => Qualifier::Invariant,
                Tok::Kw(Kw::Lowp) => Qualifier::Precision(Precision::Low),
                Tok::Kw(Kw::Mediump) => Qualifier::Precision(Precision::Medium),
                Tok::Kw(Kw::Highp) => Qualifier::Precision(Precision::High),
                Tok::Kw(Kw::Layout) => {
                    self.advance();
                    let open = self.expect(Punct::LeftParen)?;
                    let mut items = Vec::new();
                    loop {
                        let name = self.ident("a layout qualifier")?;
                        let value = if self.eat(Punct::Equal) {
                            Some(self.unary()?)
                        } else {
                            None
                        };
                        items.push(LayoutItem { name, value });
                        if !self.eat(Punct::Comma) {
                            break;
                        }
                    }
                    self.expect_close(Punct::RightParen, open)?;
                    out.push((Qualifier::Layout(items), self.span_from(span)));
                    continue;
                }
                Tok::Reserved
                    if &*self.peek().text == "noperspective"
                        && self.lang.has_at(
                            crate::target::Extension::NvShaderNoperspectiveInterpolation,
                            span.start,
                        ) =>
                {
                    Qualifier::Interpolation(Interpolation::NoPerspective)
                }
                Tok::Reserved if matches!(&*self.peek().text, "attribute" | "varying") => {
                    // ES 1.00 qualifiers: report once, then read them as their ES 3.00 twins.
                    let name = self.peek().text.clone();
                    let replacement = match (&*name, self.stage) {
                        ("attribute", _) | ("varying", Stage::Fragment) => "in",
                        _ => "out",
                    };
                    let d = Diagnostic::error(
                        Code::Es100Qualifier,
                        format!("`{name}` is GLSL ES 1.00 and is reserved in GLSL ES 3.00"),
                        span,
                    )
                    .with_label("not a qualifier in GLSL ES 3.00")
                    .with_fix(Fix::certain(
                        format!("write `{replacement}`"),
                        span,
                        replacement,
                    ))
                    .with_token(&*name);
                    if !self.suppress {
                        self.push_diag(d);
                    }
                    Qualifier::Storage(if replacement == "in" {
                        Storage::In
                    } else {
                        Storage::Out
                    })
                }
                _ => break,
            };
            self.advance();
            out.push((q, span));
        }
        Ok(out)
    }

    /// Parses a type specifier: a type keyword, a struct name or a struct definition, with an
    /// optional array size.
    pub(super) fn type_spec(&mut self) -> PResult<TypeSpec> {
        let start = self.peek().span;
        let name = match self.peek().tok {
            Tok::Kw(Kw::Struct) => TypeName::Struct(Arc::new(self.struct_decl()?)),
            Tok::Kw(k) => match type_keyword(k) {
                Some(n) => {
                    self.advance();
                    n
                }
                None => return Err(self.expected("a type")),
            },
            Tok::Ident if self.is_type_name(&self.peek().text) => {
                let name = self.peek().text.clone();
                self.advance();
                TypeName::Named(Ident { name, span: start })
            }
            _ => return Err(self.not_a_type()),
        };
        let array = if self.at(Punct::LeftBracket) {
            Some(self.array_size()?)
        } else {
            None
        };
        Ok(TypeSpec {
            name,
            array,
            span: self.span_from(start),
        })
    }

    /// Reports the current token where a type was expected: a variable hiding a struct, an
    /// unknown name, a reserved word or anything else.
    fn not_a_type(&mut self) -> Failed {
        let t = self.peek().clone();
        match &t.tok {
            Tok::Ident if self.hides_type(&t.text) => {
                let name = &t.text;
                let d = Diagnostic::error(
                    Code::UnknownType,
                    format!("`{name}` is a variable here, not a type"),
                    t.span,
                )
                .with_label("a variable hides the struct of this name")
                .with_note("a variable or parameter hides a type of the same name in its scope (GLSL ES §4.2.2)")
                .with_help("rename the variable, or use the type outside the variable's scope")
                .with_token(&**name);
                self.report(d);
                Failed
            }
            Tok::Ident => {
                let name = &t.text;
                let d =
                    Diagnostic::error(Code::UnknownType, format!("unknown type `{name}`"), t.span)
                        .with_label("not a type")
                        .with_token(&**name);
                let es300_type = matches!(
                    &**name,
                    "uint"
                        | "uvec2"
                        | "uvec3"
                        | "uvec4"
                        | "mat2x2"
                        | "mat2x3"
                        | "mat2x4"
                        | "mat3x2"
                        | "mat3x3"
                        | "mat3x4"
                        | "mat4x2"
                        | "mat4x3"
                        | "mat4x4"
                        | "sampler2DArray"
                        | "isampler2D"
                        | "isampler3D"
                        | "isamplerCube"
                        | "isampler2DArray"
                        | "usampler2D"
                        | "usampler3D"
                        | "usamplerCube"
                        | "usampler2DArray"
                        | "samplerCubeShadow"
                        | "sampler2DArrayShadow"
                );
                let d = match &**name {
                    _ if self.es100 && es300_type => d.with_help(format!(
                        "`{name}` is a GLSL ES 3.00 type: start the shader with `#version 300 es` (WebGL 2) to use it"
                    )),
                    "sampler" | "texture2D" => d,
                    "half" | "double" => d.with_help("use `float`"),
                    _ => match crate::near::type_or_keyword(name) {
                        Some((near, what)) => d
                            .with_help(format!("a {what} with a similar name exists, `{near}`"))
                            .with_fix(Fix::suggested(format!("write `{near}`"), t.span, near)),
                        None => {
                            d.with_help("declare the struct before this line, or use a built-in type")
                        }
                    },
                };
                self.report(d);
                Failed
            }
            Tok::Reserved => {
                self.advance();
                self.reserved_word(&t.text, t.span);
                self.suppress = true;
                Failed
            }
            _ => self.expected("a type"),
        }
    }

    pub(super) fn array_size(&mut self) -> PResult<ArraySize> {
        let open = self.expect(Punct::LeftBracket)?;
        let size = if self.at(Punct::RightBracket) {
            None
        } else {
            Some(Box::new(self.conditional()?))
        };
        self.expect_close(Punct::RightBracket, open)?;
        Ok(ArraySize {
            size,
            span: self.span_from(open),
        })
    }

    fn struct_decl(&mut self) -> PResult<StructDecl> {
        let start = self.bump_span(); // `struct`
        let name = match self.tok() {
            Tok::Ident | Tok::Reserved => Some(self.ident("a struct name")?),
            _ => None,
        };
        let open = self.expect(Punct::LeftBrace)?;
        let members = self.member_list(open)?;
        if let Some(n) = &name {
            self.declare_name(&n.name, true);
        }
        Ok(StructDecl {
            name,
            members,
            span: self.span_from(start),
        })
    }

    /// Member declarations up to and including the closing `}`.
    pub(super) fn member_list(&mut self, open: Span) -> PResult<Vec<MemberDecl>> {
        let mut members = Vec::new();
        while !self.at(Punct::RightBrace) && !self.at_eof() {
            let start = self.peek().span;
            let qualifiers = self.qualifiers()?;
            let spec = self.type_spec()?;
            let ty = FullType {
                span: start.to(spec.span),
                qualifiers,
                spec,
            };
            let mut names = Vec::new();
            loop {
                let n = self.ident("a member name")?;
                let a = if self.at(Punct::LeftBracket) {
                    Some(self.array_size()?)
                } else {
                    None
                };
                names.push((n, a));
                if !self.eat(Punct::Comma) {
                    break;
                }
            }
            self.expect_semicolon("the member declaration")?;
            members.push(MemberDecl {
                ty: Box::new(FullTypeEq(ty)),
                names,
                span: self.span_from(start),
            });
        }
        self.expect_close(Punct::RightBrace, open)?;
        Ok(members)
    }
}
