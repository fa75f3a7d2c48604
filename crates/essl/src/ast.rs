//! The syntax tree of a GLSL ES shader, as written (before name resolution and types).

use crate::Name;
use std::sync::Arc;

use crate::source::Span;
use crate::types::{Precision, SamplerType, ScalarKind};

/// An identifier with its span.
#[derive(Clone, Debug, PartialEq)]
pub struct Ident {
    /// The name.
    pub name: Name,
    /// Where it is written.
    pub span: Span,
}

/// A whole shader.
#[derive(Clone, Debug, Default)]
pub struct TranslationUnit {
    /// Top-level declarations in order.
    pub items: Vec<ExternalDecl>,
    /// The parser gave up before the end (nesting too deep): later declarations are missing,
    /// so "missing `main`" would be a cascade.
    pub truncated: bool,
}

/// A top-level declaration.
#[derive(Clone, Debug)]
pub enum ExternalDecl {
    /// A function definition (with a body).
    Function(FunctionDef),
    /// A function prototype (`float f(float);`).
    Prototype(FunctionProto),
    /// A variable, struct, block, precision or invariant declaration.
    Declaration(Declaration),
}

/// A function's signature.
#[derive(Clone, Debug)]
pub struct FunctionProto {
    /// Return type (with qualifiers: only a precision is allowed).
    pub ret: FullType,
    /// The name.
    pub name: Ident,
    /// The parameters (an empty list for `f()` and `f(void)`).
    pub params: Vec<Param>,
    /// From the return type to the closing parenthesis.
    pub span: Span,
}

/// A function definition.
#[derive(Clone, Debug)]
pub struct FunctionDef {
    /// Its signature.
    pub proto: FunctionProto,
    /// Its body.
    pub body: Block,
}

/// A parameter declaration.
#[derive(Clone, Debug)]
pub struct Param {
    /// Qualifiers (`const`, `in`/`out`/`inout`, precision) and type.
    pub ty: FullType,
    /// Its name (optional in a prototype).
    pub name: Option<Ident>,
    /// `float x[3]`: the array size after the name.
    pub array: Option<ArraySize>,
    /// The whole parameter.
    pub span: Span,
}

/// A storage qualifier.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Storage {
    /// `const`
    Const,
    /// `in` (global: shader input; parameter: copied in)
    In,
    /// `out`
    Out,
    /// `inout` (parameters only)
    Inout,
    /// `uniform`
    Uniform,
    /// `attribute` (GLSL ES 1.00: a vertex shader input)
    Attribute,
    /// `varying` (GLSL ES 1.00: a vertex shader output or a fragment shader input)
    Varying,
}

impl Storage {
    /// The keyword.
    pub fn as_str(self) -> &'static str {
        match self {
            Storage::Const => "const",
            Storage::In => "in",
            Storage::Out => "out",
            Storage::Inout => "inout",
            Storage::Uniform => "uniform",
            Storage::Attribute => "attribute",
            Storage::Varying => "varying",
        }
    }
}

/// An interpolation qualifier.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Interpolation {
    /// `smooth`
    Smooth,
    /// `flat`
    Flat,
    /// `noperspective` (`GL_NV_shader_noperspective_interpolation`): linear in screen space.
    NoPerspective,
}

/// One qualifier as written, in source order (ES 3.00 constrains the order).
#[derive(Clone, Debug, PartialEq)]
pub enum Qualifier {
    /// `const`, `in`, `out`, `inout`, `uniform`
    Storage(Storage),
    /// `centroid`
    Centroid,
    /// `smooth`, `flat`
    Interpolation(Interpolation),
    /// `invariant`
    Invariant,
    /// `lowp`, `mediump`, `highp`
    Precision(Precision),
    /// `layout(...)`
    Layout(Vec<LayoutItem>),
}

/// One `name` or `name = value` in `layout(...)`.
#[derive(Clone, Debug, PartialEq)]
pub struct LayoutItem {
    /// The identifier, as written (the checker matches layout names).
    pub name: Ident,
    /// The value, for `location = 2`.
    pub value: Option<Expr>,
}

/// A type with its qualifiers.
#[derive(Clone, Debug)]
pub struct FullType {
    /// Qualifiers in source order, each with its span.
    pub qualifiers: Vec<(Qualifier, Span)>,
    /// The type.
    pub spec: TypeSpec,
    /// From the first qualifier to the end of the type.
    pub span: Span,
}

impl FullType {
    /// The storage qualifier, if any.
    pub fn storage(&self) -> Option<(Storage, Span)> {
        self.qualifiers.iter().find_map(|(q, s)| match q {
            Qualifier::Storage(st) => Some((*st, *s)),
            _ => None,
        })
    }

    /// The precision qualifier, if any.
    pub fn precision(&self) -> Option<(Precision, Span)> {
        self.qualifiers.iter().find_map(|(q, s)| match q {
            Qualifier::Precision(p) => Some((*p, *s)),
            _ => None,
        })
    }

    /// The interpolation qualifier, if any.
    pub fn interpolation(&self) -> Option<(Interpolation, Span)> {
        self.qualifiers.iter().find_map(|(q, s)| match q {
            Qualifier::Interpolation(i) => Some((*i, *s)),
            _ => None,
        })
    }

    /// Whether `invariant` is given.
    pub fn invariant(&self) -> Option<Span> {
        self.qualifiers
            .iter()
            .find_map(|(q, s)| matches!(q, Qualifier::Invariant).then_some(*s))
    }

    /// Whether `centroid` is given.
    pub fn centroid(&self) -> Option<Span> {
        self.qualifiers
            .iter()
            .find_map(|(q, s)| matches!(q, Qualifier::Centroid).then_some(*s))
    }

    /// All `layout(...)` items.
    pub fn layout(&self) -> Vec<&LayoutItem> {
        self.qualifiers
            .iter()
            .filter_map(|(q, _)| match q {
                Qualifier::Layout(items) => Some(items.iter()),
                _ => None,
            })
            .flatten()
            .collect()
    }
}

/// The basic (non-array) part of a type specifier.
#[derive(Clone, Debug, PartialEq)]
pub enum TypeName {
    /// `void`
    Void,
    /// `float`, `int`, `uint`, `bool`
    Scalar(ScalarKind),
    /// `vec3`, `ivec2`, …
    Vector(ScalarKind, u8),
    /// `mat3`, `mat2x4`, …
    Matrix {
        /// Columns.
        cols: u8,
        /// Rows.
        rows: u8,
    },
    /// A sampler type.
    Sampler(SamplerType),
    /// A struct defined right here (`struct S { … }`).
    Struct(Arc<StructDecl>),
    /// A struct's name.
    Named(Ident),
}

/// A type specifier: a basic type with an optional array size (`float[3]`).
#[derive(Clone, Debug, PartialEq)]
pub struct TypeSpec {
    /// The basic type.
    pub name: TypeName,
    /// `float[3]` / `float[]`.
    pub array: Option<ArraySize>,
    /// Where it is written.
    pub span: Span,
}

/// An array size: `[N]` or `[]`.
#[derive(Clone, Debug, PartialEq)]
pub struct ArraySize {
    /// The size expression; `None` for `[]`.
    pub size: Option<Box<Expr>>,
    /// From `[` to `]`.
    pub span: Span,
}

/// A struct definition.
#[derive(Clone, Debug, PartialEq)]
pub struct StructDecl {
    /// The struct's name (`None`: anonymous).
    pub name: Option<Ident>,
    /// Member declarations.
    pub members: Vec<MemberDecl>,
    /// From `struct` to `}`.
    pub span: Span,
}

/// One member declaration line in a struct or a block: `highp vec3 a, b[2];`.
#[derive(Clone, Debug, PartialEq)]
pub struct MemberDecl {
    /// Qualifiers and type.
    pub ty: FullTypeRef,
    /// The declared names.
    pub names: Vec<(Ident, Option<ArraySize>)>,
    /// The whole line.
    pub span: Span,
}

/// A [`FullType`] inside a struct (boxed to keep the enum small and comparable).
pub type FullTypeRef = Box<FullTypeEq>;

/// A [`FullType`] that can be compared (for struct definitions).
#[derive(Clone, Debug)]
pub struct FullTypeEq(pub FullType);

impl PartialEq for FullTypeEq {
    fn eq(&self, other: &Self) -> bool {
        self.0.qualifiers == other.0.qualifiers && self.0.spec == other.0.spec
    }
}

/// A declaration.
#[derive(Clone, Debug)]
pub enum Declaration {
    /// `[qualifiers] type a = x, b[2];` (possibly with no names: `struct S {…};`).
    Variables {
        /// Qualifiers and type.
        ty: FullType,
        /// The declared names.
        declarators: Vec<Declarator>,
        /// The whole declaration.
        span: Span,
    },
    /// `precision highp float;`
    Precision {
        /// The precision.
        precision: Precision,
        /// The type it applies to.
        ty: TypeSpec,
        /// The whole statement.
        span: Span,
    },
    /// `layout(std140) uniform Name { … } instance[N];`
    Block {
        /// Qualifiers (`uniform` and maybe a layout).
        qualifiers: Vec<(Qualifier, Span)>,
        /// The block's name.
        name: Ident,
        /// Members.
        members: Vec<MemberDecl>,
        /// An instance name and array size.
        instance: Option<(Ident, Option<ArraySize>)>,
        /// The whole declaration.
        span: Span,
    },
    /// `invariant gl_Position, v;`
    Invariant {
        /// The names.
        names: Vec<Ident>,
        /// The whole declaration.
        span: Span,
    },
    /// Qualifiers alone: `layout(std140) uniform;`, `precise;`.
    Qualifiers {
        /// The qualifiers.
        qualifiers: Vec<(Qualifier, Span)>,
        /// The whole declaration.
        span: Span,
    },
}

/// One declared name with its array size and initializer.
#[derive(Clone, Debug)]
pub struct Declarator {
    /// The name.
    pub name: Ident,
    /// `a[3]`, `a[]`.
    pub array: Option<ArraySize>,
    /// `= expr`.
    pub init: Option<Expr>,
    /// From the name to the end of the initializer.
    pub span: Span,
}

/// A block of statements in braces.
#[derive(Clone, Debug, Default)]
pub struct Block {
    /// The statements.
    pub stmts: Vec<Stmt>,
    /// From `{` to `}`.
    pub span: Span,
}

/// A statement.
#[derive(Clone, Debug)]
pub struct Stmt {
    /// What it is.
    pub kind: StmtKind,
    /// Where.
    pub span: Span,
}

/// The kinds of statement.
#[derive(Clone, Debug)]
pub enum StmtKind {
    /// A declaration.
    Decl(Declaration),
    /// An expression followed by `;`.
    Expr(Expr),
    /// `{ … }` (a new scope).
    Block(Block),
    /// `if (c) a else b`
    If(Expr, Box<Stmt>, Option<Box<Stmt>>),
    /// `switch (e) { … }`: the body's statements, with `case`/`default` labels among them.
    Switch(Expr, Block),
    /// `case e:`
    Case(Expr),
    /// `default:`
    Default,
    /// `while (c) body`
    While(Box<Condition>, Box<Stmt>),
    /// `do body while (c);`
    DoWhile(Box<Stmt>, Expr),
    /// `for (init; cond; step) body`
    For {
        /// The init statement (a declaration or an expression statement; may be empty).
        init: Box<Stmt>,
        /// The condition (absent means true).
        cond: Option<Box<Condition>>,
        /// The step expression.
        step: Option<Box<Expr>>,
        /// The body.
        body: Box<Stmt>,
    },
    /// `continue;`
    Continue,
    /// `break;`
    Break,
    /// `return e;`
    Return(Option<Expr>),
    /// `discard;`
    Discard,
    /// `;`
    Empty,
    /// A statement that failed to parse (already reported).
    Error,
}

/// A loop condition: an expression, or a declaration with initializer (`while (bool b = f())`).
#[derive(Clone, Debug)]
pub enum Condition {
    /// An expression.
    Expr(Expr),
    /// `type name = init`.
    Decl(FullType, Ident, Expr),
}

/// An expression.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    /// What it is.
    pub kind: ExprKind,
    /// Where.
    pub span: Span,
}

/// Unary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    /// `+x`
    Plus,
    /// `-x`
    Neg,
    /// `!x`
    Not,
    /// `~x`
    BitNot,
    /// `++x`
    PreInc,
    /// `--x`
    PreDec,
    /// `x++`
    PostInc,
    /// `x--`
    PostDec,
}

impl UnaryOp {
    /// The operator's text.
    pub fn as_str(self) -> &'static str {
        match self {
            UnaryOp::Plus => "+",
            UnaryOp::Neg => "-",
            UnaryOp::Not => "!",
            UnaryOp::BitNot => "~",
            UnaryOp::PreInc | UnaryOp::PostInc => "++",
            UnaryOp::PreDec | UnaryOp::PostDec => "--",
        }
    }
}

/// Binary operators.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
#[allow(missing_docs)]
pub enum BinaryOp {
    Add,
    Sub,
    Mul,
    Div,
    Mod,
    Shl,
    Shr,
    Less,
    Greater,
    LessEq,
    GreaterEq,
    Eq,
    NotEq,
    BitAnd,
    BitXor,
    BitOr,
    And,
    Xor,
    Or,
}

impl BinaryOp {
    /// The operator's text.
    pub fn as_str(self) -> &'static str {
        use BinaryOp::*;
        match self {
            Add => "+",
            Sub => "-",
            Mul => "*",
            Div => "/",
            Mod => "%",
            Shl => "<<",
            Shr => ">>",
            Less => "<",
            Greater => ">",
            LessEq => "<=",
            GreaterEq => ">=",
            Eq => "==",
            NotEq => "!=",
            BitAnd => "&",
            BitXor => "^",
            BitOr => "|",
            And => "&&",
            Xor => "^^",
            Or => "||",
        }
    }
}

/// The kinds of expression.
#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    /// A name.
    Ident(Ident),
    /// An integer literal (value, `u` suffix).
    Int(u64, bool),
    /// A float literal.
    Float(f32),
    /// `true` / `false`.
    Bool(bool),
    /// A unary operation.
    Unary(UnaryOp, Box<Expr>),
    /// A binary operation.
    Binary(BinaryOp, Box<Expr>, Box<Expr>),
    /// `a = b` (`None`) or `a op= b`.
    Assign(Option<BinaryOp>, Box<Expr>, Box<Expr>),
    /// `c ? a : b`
    Ternary(Box<Expr>, Box<Expr>, Box<Expr>),
    /// `a, b`
    Comma(Box<Expr>, Box<Expr>),
    /// `a[i]`
    Index(Box<Expr>, Box<Expr>),
    /// `a.name`: a struct member or a swizzle.
    Field(Box<Expr>, Ident),
    /// A call to a function or a constructor.
    Call(Callee, Vec<Expr>),
    /// A part that failed to parse (already reported).
    Error,
}

/// What a call calls.
#[derive(Clone, Debug, PartialEq)]
pub enum Callee {
    /// A function (user or built-in), or a struct constructor by name.
    Name(Ident),
    /// A constructor of a type keyword or array type: `vec3(…)`, `float[3](…)`.
    Type(TypeSpec),
    /// `a.length()`.
    Length(Box<Expr>),
}
