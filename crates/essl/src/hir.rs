//! The checked shader: every name resolved, every expression typed, constants folded.
//!
//! This is what the checker produces and what lowering (to naga IR), reflection and linking
//! read. Spans still point into the original text.

pub mod visit;

use crate::Name;

pub use crate::ast::{BinaryOp, Interpolation};
pub use crate::builtins::{BuiltinFn, BuiltinVar};
use crate::source::Span;
use crate::types::{Precision, StructDef, Type};
use crate::Stage;

/// Index of a global variable in [`Module::globals`].
pub type GlobalId = usize;
/// Index of a function in [`Module::functions`].
pub type FuncId = usize;
/// Index of a local variable in [`Function::locals`].
pub type LocalId = usize;

/// A checked shader.
#[derive(Clone, Debug)]
pub struct Module {
    /// The stage.
    pub stage: Stage,
    /// The language version it was checked as: [`crate::Version::Es100`] or
    /// [`crate::Version::Es300`].
    pub version: crate::Version,
    /// Struct types; [`Type::Struct`] indexes this table.
    pub structs: Vec<StructDef>,
    /// Global variables in declaration order (uniforms, inputs, outputs, plain globals,
    /// uniform-block members).
    pub globals: Vec<Global>,
    /// Functions with bodies, in declaration order.
    pub functions: Vec<Function>,
    /// `main`.
    pub entry: Option<FuncId>,
    /// Uniform blocks.
    pub blocks: Vec<UniformBlock>,
    /// Built-in variables the shader uses (directly or through a called function).
    pub used_builtins: Vec<BuiltinVar>,
    /// `#pragma STDGL invariant(all)`.
    pub invariant_all: bool,
    /// Built-in variables declared `invariant` (`invariant gl_Position;`).
    pub invariant_builtins: Vec<BuiltinVar>,
    /// The length of `gl_FragData` (`gl_MaxDrawBuffers`) in a GLSL ES 1.00 fragment shader.
    pub frag_data_len: u32,
    /// A GLSL ES 1.00 fragment shader that enabled `GL_EXT_draw_buffers`: what it writes to
    /// `gl_FragColor` goes to every draw buffer (`gl_FragData[0..frag_data_len]`).
    pub frag_color_broadcast: bool,
}

/// Where a global variable lives.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GlobalKind {
    /// A plain global variable (private to one invocation).
    Private,
    /// A `const` global (always has a folded value).
    Const,
    /// A loose `uniform`.
    Uniform,
    /// A member of a uniform block: (block, member index).
    BlockMember(usize, usize),
    /// A shader input (`in`): a vertex attribute or a fragment varying.
    Input,
    /// A shader output (`out`): a vertex varying or a fragment output.
    Output,
}

/// A global variable.
#[derive(Clone, Debug)]
pub struct Global {
    /// Its name.
    pub name: Name,
    /// Its type.
    pub ty: Type,
    /// Where it lives.
    pub kind: GlobalKind,
    /// Its precision (declared or default), for types that have one.
    pub precision: Option<Precision>,
    /// `flat` / `smooth` (inputs and outputs).
    pub interpolation: Option<Interpolation>,
    /// `centroid`.
    pub centroid: bool,
    /// `invariant` (declared or by `invariant name;`).
    pub invariant: bool,
    /// `layout(location = N)`.
    pub location: Option<u32>,
    /// The initializer: a folded constant, or an expression evaluated at the start of `main`.
    pub init: Option<Init>,
    /// The declarator's span (the name).
    pub span: Span,
    /// Whether the entry point (through any call) reads or writes it (WebGL's static use).
    pub used: bool,
}

/// An initializer.
#[derive(Clone, Debug)]
pub enum Init {
    /// A constant value.
    Const(ConstValue),
    /// An expression (for a non-const global with a non-constant initializer).
    Expr(Expr),
}

/// A uniform block.
#[derive(Clone, Debug)]
pub struct UniformBlock {
    /// The block's name.
    pub name: Name,
    /// The instance name (`None`: members are visible at global scope).
    pub instance: Option<Name>,
    /// Instance array size.
    pub array: Option<u32>,
    /// Members: (name, type, precision, row_major).
    pub members: Vec<(Name, Type, Option<Precision>, bool)>,
    /// `std140` (the default in WebGL), `shared` or `packed`.
    pub layout: BlockLayout,
    /// Where it is declared.
    pub span: Span,
    /// Whether the entry point uses it.
    pub used: bool,
}

/// A uniform block's memory layout.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BlockLayout {
    /// `std140`
    Std140,
    /// `shared` (laid out as std140 here)
    Shared,
    /// `packed` (laid out as std140 here)
    Packed,
}

/// How a parameter passes its value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParamMode {
    /// `in` (the default): copied in.
    In,
    /// `out`: copied out.
    Out,
    /// `inout`: copied in and out.
    InOut,
}

/// A function parameter.
#[derive(Clone, Debug)]
pub struct Param {
    /// Its name (parameters without a name get an internal one).
    pub name: Name,
    /// Its type.
    pub ty: Type,
    /// How it passes.
    pub mode: ParamMode,
    /// `const in`.
    pub is_const: bool,
    /// Its precision.
    pub precision: Option<Precision>,
    /// Where it is declared.
    pub span: Span,
}

/// A local variable.
#[derive(Clone, Debug)]
pub struct Local {
    /// Its name.
    pub name: Name,
    /// Its type.
    pub ty: Type,
    /// `const` locals have a folded value and are never assigned.
    pub constant: Option<ConstValue>,
    /// Its precision.
    pub precision: Option<Precision>,
    /// Where it is declared.
    pub span: Span,
}

/// A user function with a body.
#[derive(Clone, Debug)]
pub struct Function {
    /// Its name.
    pub name: Name,
    /// The mangled name (name + parameter types) that distinguishes overloads.
    pub signature: String,
    /// Its parameters.
    pub params: Vec<Param>,
    /// Its return type.
    pub ret: Type,
    /// The precision of the return value.
    pub ret_precision: Option<Precision>,
    /// Locals (parameters are not locals).
    pub locals: Vec<Local>,
    /// The body.
    pub body: Vec<Stmt>,
    /// Functions it calls directly.
    pub calls: Vec<FuncId>,
    /// Where it is defined (the name).
    pub span: Span,
    /// Whether the entry point (through any call) calls it.
    pub used: bool,
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
#[non_exhaustive]
#[derive(Clone, Debug)]
pub enum StmtKind {
    /// An expression evaluated for its effects.
    Expr(Expr),
    /// A local's declaration, with its initializer.
    Local(LocalId, Option<Expr>),
    /// A nested block.
    Block(Vec<Stmt>),
    /// `if`
    If(Expr, Vec<Stmt>, Vec<Stmt>),
    /// Any loop: `for`, `while`, `do … while`.
    Loop {
        /// Statements before the loop (a `for`'s init).
        init: Vec<Stmt>,
        /// The condition (`None`: always true); evaluated before the body unless `do_while`.
        cond: Option<Box<Cond>>,
        /// The step (a `for`'s increment), evaluated after the body and after `continue`.
        step: Option<Expr>,
        /// The body.
        body: Vec<Stmt>,
        /// `do … while`: the condition is tested after the body.
        do_while: bool,
    },
    /// `switch`: the selector and its cases in order.
    Switch(Expr, Vec<SwitchCase>),
    /// `break`
    Break,
    /// `continue`
    Continue,
    /// `return`
    Return(Option<Expr>),
    /// `discard`
    Discard,
}

/// A loop condition, possibly declaring a variable.
#[derive(Clone, Debug)]
pub enum Cond {
    /// A boolean expression.
    Expr(Expr),
    /// `type name = init`: declares a local each iteration and tests it.
    Decl(LocalId, Expr),
}

/// A `case` (or `default`) of a switch, with the statements up to the next label.
#[derive(Clone, Debug)]
pub struct SwitchCase {
    /// The label's value (`None`: `default`).
    pub value: Option<i64>,
    /// The statements.
    pub body: Vec<Stmt>,
    /// Whether control falls through into the next case.
    pub fall_through: bool,
    /// The label's span.
    pub span: Span,
}

/// One scalar value of a constant.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Scalar {
    /// A float.
    F(f32),
    /// An int.
    I(i32),
    /// A uint.
    U(u32),
    /// A bool.
    B(bool),
}

/// A constant value.
#[derive(Clone, Debug, PartialEq)]
pub enum ConstValue {
    /// A scalar, vector (components) or matrix (column-major components).
    Basic(Vec<Scalar>),
    /// An array (elements) or struct (members).
    Composite(Vec<ConstValue>),
}

/// A typed expression.
#[derive(Clone, Debug)]
pub struct Expr {
    /// What it is.
    pub kind: ExprKind,
    /// Its type.
    pub ty: Type,
    /// Where.
    pub span: Span,
}

/// Unary operations after checking.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    /// `-x`
    Neg,
    /// `!x`
    Not,
    /// `~x`
    BitNot,
}

/// The kinds of expression.
#[non_exhaustive]
#[derive(Clone, Debug)]
pub enum ExprKind {
    /// An expression that failed to check; its type is [`Type::Void`] and the error has been
    /// reported. Rules that meet one stay silent, so one mistake gives one diagnostic. Only a
    /// shader with errors contains one, and such a shader is never lowered.
    Error,
    /// A constant (literals, folded constant expressions, `const` variables).
    Const(ConstValue),
    /// A local variable.
    Local(LocalId),
    /// A parameter of the current function.
    Param(usize),
    /// A global variable.
    Global(GlobalId),
    /// A built-in variable.
    BuiltinVar(BuiltinVar),
    /// A unary operation (`+x` is dropped).
    Unary(UnaryOp, Box<Expr>),
    /// A binary operation, operands as typed (scalar–vector mixes kept; lowering splats).
    Binary(BinaryOp, Box<Expr>, Box<Expr>),
    /// `lhs = rhs` or `lhs op= rhs`; the value is the new value of `lhs`.
    Assign(Option<BinaryOp>, Box<Expr>, Box<Expr>),
    /// `++`/`--`: (increment?, prefix?, operand).
    IncDec(bool, bool, Box<Expr>),
    /// `c ? a : b` (only the chosen side is evaluated).
    Select(Box<Expr>, Box<Expr>, Box<Expr>),
    /// `a, b`
    Comma(Box<Expr>, Box<Expr>),
    /// `base[index]` on an array, matrix or vector.
    Index(Box<Expr>, Box<Expr>),
    /// A struct member by index.
    Member(Box<Expr>, usize),
    /// A swizzle: component indices (1 to 4).
    Swizzle(Box<Expr>, Vec<u8>),
    /// A call to a user function.
    Call(FuncId, Vec<Expr>),
    /// A call to a built-in function.
    Builtin(BuiltinFn, Vec<Expr>),
    /// A constructor of the expression's type from the arguments.
    Construct(Vec<Expr>),
    /// An access to a member of a named uniform block instance: (block, array index, member).
    BlockMember(usize, Option<Box<Expr>>, usize),
}

impl Expr {
    /// The expression a write to this one writes into: itself, or the base of the indices,
    /// members and swizzles it selects (`a[i].xy = …` writes `a`).
    pub fn write_root(&self) -> &Expr {
        match &self.kind {
            ExprKind::Index(b, _) | ExprKind::Member(b, _) | ExprKind::Swizzle(b, _) => {
                b.write_root()
            }
            _ => self,
        }
    }

    /// Whether evaluating it has a side effect: it writes a variable, or calls a user function
    /// (or `modf`, which writes its `out` argument).
    pub fn has_effects(&self) -> bool {
        match &self.kind {
            ExprKind::Assign(..) | ExprKind::IncDec(..) | ExprKind::Call(..) => true,
            ExprKind::Builtin(op, args) => {
                *op == BuiltinFn::Modf || args.iter().any(Expr::has_effects)
            }
            ExprKind::Unary(_, a) | ExprKind::Member(a, _) | ExprKind::Swizzle(a, _) => {
                a.has_effects()
            }
            ExprKind::Binary(_, a, b) | ExprKind::Comma(a, b) | ExprKind::Index(a, b) => {
                a.has_effects() || b.has_effects()
            }
            ExprKind::Select(c, a, b) => c.has_effects() || a.has_effects() || b.has_effects(),
            ExprKind::Construct(args) => args.iter().any(Expr::has_effects),
            ExprKind::BlockMember(_, Some(i), _) => i.has_effects(),
            _ => false,
        }
    }

    /// The folded value, when the expression is a constant.
    pub fn as_const(&self) -> Option<&ConstValue> {
        match &self.kind {
            ExprKind::Const(c) => Some(c),
            _ => None,
        }
    }
}

impl ConstValue {
    /// The scalar components of a basic constant.
    pub fn scalars(&self) -> Option<&[Scalar]> {
        match self {
            ConstValue::Basic(v) => Some(v),
            ConstValue::Composite(_) => None,
        }
    }

    /// The value of a scalar integer constant.
    pub fn as_int(&self) -> Option<i64> {
        match self.scalars()? {
            [Scalar::I(i)] => Some(*i as i64),
            [Scalar::U(u)] => Some(*u as i64),
            _ => None,
        }
    }
}

impl Scalar {
    /// As f64 (bools are 0/1).
    pub fn as_f64(self) -> f64 {
        match self {
            Scalar::F(f) => f as f64,
            Scalar::I(i) => i as f64,
            Scalar::U(u) => u as f64,
            Scalar::B(b) => b as u8 as f64,
        }
    }
}
