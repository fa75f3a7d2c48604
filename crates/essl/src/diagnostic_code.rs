//! The codes of essl's diagnostics, one variant per code: the stable kebab-case name a tool
//! matches on (`missing-semicolon`) and, in each variant's doc comment, what the diagnostic
//! means and the GLSL ES 3.00 or WebGL2 rule behind it. These doc comments are the codes'
//! documentation.
//!
//! Each variant is declared once, with its name and its documentation, by the `codes!` macro,
//! which derives [`Code::as_str`], [`Code::from_name`], [`Code::doc`] and [`Code::ALL`] from the
//! same list.

use std::fmt;
use std::str::FromStr;

/// Declares [`Code`] from `Variant = "name"` lines with their doc comments.
macro_rules! codes {
    ($($(#[doc = $doc:literal])* $variant:ident = $name:literal,)*) => {
        /// The code of a diagnostic: what kind of problem it reports.
        #[non_exhaustive]
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub enum Code {
            $($(#[doc = $doc])* $variant,)*
        }

        impl Code {
            /// Every code, in declaration order (by the pass that reports it).
            pub const ALL: &'static [Code] = &[$(Code::$variant,)*];

            /// The code's stable kebab-case name (`missing-semicolon`).
            pub fn as_str(self) -> &'static str {
                match self {
                    $(Code::$variant => $name,)*
                }
            }

            /// The code's documentation: its doc comment, one source line per line, with the
            /// leading space of each line removed (`essl explain` prints it).
            fn doc_lines(self) -> &'static [&'static str] {
                match self {
                    $(Code::$variant => &[$($doc,)*],)*
                }
            }

            /// The code named `name`, if there is one.
            pub fn from_name(name: &str) -> Option<Code> {
                match name {
                    $($name => Some(Code::$variant),)*
                    _ => None,
                }
            }
        }
    };
}

codes! {
    // ----- reading the text (`lex`, `token`) -----

    /// A `/*` comment is never closed with `*/` before the end of the file.
    UnterminatedComment = "unterminated-comment",
    /// A no-break space (U+00A0), invisible and easy to paste from a web page: an error in code,
    /// where GLSL ES allows only ASCII white space, and a warning in a comment, where it is
    /// harmless.
    NoBreakSpace = "no-break-space",
    /// A numeric literal that is malformed, such as an octal literal with a digit 8 or 9 or a
    /// suffix GLSL ES does not have.
    InvalidNumber = "invalid-number",
    /// An integer literal, or an integer in a `#if` expression, that does not fit in 32 bits
    /// (GLSL ES 3.00 §4.1.3 makes such a literal an error).
    IntegerOverflow = "integer-overflow",
    /// A floating-point literal too large for a 32-bit float, which becomes infinity.
    FloatLiteralOverflow = "float-literal-overflow",

    // ----- the preprocessor (`preprocess`) -----

    /// A `#version` the target does not compile: a number other than `100` and `300 es`, or
    /// `300 es` for a WebGL 1 context, which compiles GLSL ES 1.00 only.
    UnsupportedVersion = "unsupported-version",
    /// A malformed `#version` line: no version number, or `#version 300` without the `es`
    /// profile.
    InvalidVersion = "invalid-version",
    /// `#version` after code or other directives: it must come before anything but comments
    /// and white space.
    VersionNotFirst = "version-not-first",
    /// `#version 300 es` on a line other than the first: WebGL2 requires it on the very first
    /// line, so the shader would be compiled as GLSL ES 1.00.
    VersionNotFirstLine = "version-not-first-line",
    /// A `#` followed by a name that is not a directive (`#include`), or by something that is
    /// not a name.
    UnknownDirective = "unknown-directive",
    /// A `#` or `##` in code, outside the start of a directive line.
    StrayHash = "stray-hash",
    /// Tokens after a directive that takes no more (`#endif FOO`, `#else x`).
    ExtraTokens = "extra-tokens",
    /// A character GLSL ES source may not contain (GLSL ES 3.00 §3.1 allows a subset of
    /// ASCII), outside a comment.
    InvalidCharacter = "invalid-character",
    /// An identifier or number longer than the target allows anywhere in the text (a skipped
    /// group included): 256 characters in WebGL 1 (WebGL 1.0 "Maximum GLSL Token Size"), 1024 in
    /// WebGL 2 for both language versions.
    IdentifierTooLong = "identifier-too-long",
    /// `#define` or `#undef` with no macro name.
    MissingMacroName = "missing-macro-name",
    /// `#define` or `#undef` followed by something that is not an identifier.
    InvalidMacroName = "invalid-macro-name",
    /// `#define` or `#undef` of a predefined macro (`__LINE__`, `__FILE__`, `__VERSION__`,
    /// `GL_ES`), which GLSL ES forbids.
    PredefinedMacroRedefined = "predefined-macro-redefined",
    /// `#undef` of a predefined macro (`__LINE__`, `__FILE__`, `__VERSION__`, `GL_ES`).
    PredefinedMacroUndefined = "predefined-macro-undefined",
    /// A macro named `defined` or starting with `GL_`, which GLSL ES reserves.
    ReservedMacroName = "reserved-macro-name",
    /// A warning: a macro name containing `__`, which GLSL ES reserves for the implementation.
    DoubleUnderscoreMacroName = "double-underscore-macro-name",
    /// The parameter list of a function-like macro is not closed with `)`.
    UnterminatedMacroParameters = "unterminated-macro-parameters",
    /// The same parameter name appears twice in a macro's parameter list.
    DuplicateMacroParameter = "duplicate-macro-parameter",
    /// Something other than a name or `,` in a macro's parameter list.
    InvalidMacroParameters = "invalid-macro-parameters",
    /// A warning: `#` or `##` in a macro's replacement; GLSL ES has neither stringizing nor
    /// token pasting, so they stay as they are.
    TokenPasting = "token-pasting",
    /// A warning: the shader `#define`s a macro that the compile options already define; the
    /// shader's definition is used.
    OptionMacroRedefined = "option-macro-redefined",
    /// A macro defined again with a different replacement or parameters: GLSL ES allows only
    /// identical redefinitions.
    MacroRedefinition = "macro-redefinition",
    /// `#undef` of a macro inside the arguments of a call of that same macro.
    MacroUndefinedWhileExpanding = "macro-undefined-while-expanding",
    /// A function-like macro called with the wrong number of arguments.
    MacroArgumentCount = "macro-argument-count",
    /// The `(` of a function-like macro's call is never closed.
    UnterminatedMacroCall = "unterminated-macro-call",
    /// A macro whose expansion needs more than 10,000 tokens at once: a bound on the time and
    /// memory that hostile input can take.
    MacroExpansionTooLarge = "macro-expansion-too-large",
    /// Macro calls nested more than 1,000 levels deep in arguments, deeper than WebGL
    /// implementations accept.
    MacroNestingTooDeep = "macro-nesting-too-deep",
    /// `defined` produced by a macro's expansion in `#if`: undefined behaviour in GLSL ES 3.00,
    /// which WebGL rejects.
    DefinedFromMacro = "defined-from-macro",
    /// `defined` in `#if` not followed by a macro name (or `(NAME)`).
    InvalidDefined = "invalid-defined",
    /// `#if` or `#elif` with no expression.
    MissingExpression = "missing-expression",
    /// A malformed `#if` or `#elif` expression: a missing operand or `)`, or an operator the
    /// preprocessor does not have.
    InvalidExpression = "invalid-expression",
    /// An identifier in `#if` that is not a defined macro: GLSL ES 3.00 makes it an error
    /// rather than reading it as 0 as C does.
    UndefinedMacroInIf = "undefined-macro-in-if",
    /// A floating-point number or a malformed integer in a `#if` expression, which takes
    /// integers only.
    NonIntegerInExpression = "non-integer-in-expression",
    /// Division or remainder by zero in a `#if` expression, or in a constant expression of the
    /// shader (a warning there: the result is undefined, and Chromium compiles the shader with
    /// the value ANGLE folds, the type's largest integer, ±∞, or NaN for `0.0 / 0.0`).
    DivisionByZero = "division-by-zero",
    /// A shift in a `#if` expression by a negative amount or by 32 or more.
    InvalidShift = "invalid-shift",
    /// A `#if` expression nested more than 256 levels deep.
    ExpressionTooDeep = "expression-too-deep",
    /// `#elif` with no open `#if`.
    ElifWithoutIf = "elif-without-if",
    /// `#elif` after the `#else` of the same conditional.
    ElifAfterElse = "elif-after-else",
    /// `#else` with no open `#if`.
    ElseWithoutIf = "else-without-if",
    /// A second `#else` in one conditional.
    ElseAfterElse = "else-after-else",
    /// `#endif` with no open `#if`.
    EndifWithoutIf = "endif-without-if",
    /// A `#if`, `#ifdef` or `#ifndef` never closed with `#endif`.
    UnterminatedConditional = "unterminated-conditional",
    /// An `#error` directive in a group that is not skipped: the shader fails with its text.
    ErrorDirective = "error-directive",
    /// A warning: a `#pragma` that is malformed or unknown, which is ignored.
    InvalidPragma = "invalid-pragma",
    /// `#pragma STDGL invariant(all)` in a fragment shader; GLSL ES 3.00 allows it only in
    /// vertex shaders.
    InvariantAllInFragmentShader = "invariant-all-in-fragment-shader",
    /// `#extension` with no extension name.
    InvalidExtensionDirective = "invalid-extension-directive",
    /// `#extension` followed by something that is not a name.
    InvalidExtensionName = "invalid-extension-name",
    /// `#extension NAME` without `: behavior`, or with a behavior other than `require`,
    /// `enable`, `warn` or `disable`.
    InvalidExtensionBehavior = "invalid-extension-behavior",
    /// `#extension all : require` or `: enable`; `all` takes only `warn` or `disable`.
    ExtensionAllBehavior = "extension-all-behavior",
    /// An extension essl does not support: an error when it is required, a warning when it is
    /// only enabled.
    ExtensionNotSupported = "extension-not-supported",
    /// A built-in function or variable of a WebGL 1 extension (`dFdx`, `texture2DLodEXT`,
    /// `gl_FragDepthEXT`, `gl_FragData[1]`) in a shader that has not enabled the extension with
    /// `#extension NAME : enable` (or whose context has not enabled it).
    ExtensionRequired = "extension-required",
    /// `#extension` after the first declaration: GLSL ES 3.00 puts extension directives before
    /// any code.
    ExtensionAfterCode = "extension-after-code",
    /// `#line` without a line number.
    InvalidLineDirective = "invalid-line-directive",

    // ----- parsing (`parse`) -----

    /// A token the grammar does not allow where it stands (`expected an expression, found
    /// `;``).
    SyntaxError = "syntax-error",
    /// A statement or declaration not ended with `;`; reported at the end of the line that
    /// lacks it, with a fix that inserts it.
    MissingSemicolon = "missing-semicolon",
    /// A keyword used as a name (`float in = 1.0;`).
    KeywordAsIdentifier = "keyword-as-identifier",
    /// A word GLSL ES 3.00 reserves for future use (`class`, `union`, `half`, …), used as a
    /// name or a type (GLSL ES 3.00 §3.8).
    ReservedWord = "reserved-word",
    /// `attribute` or `varying`: GLSL ES 1.00 qualifiers, reserved in 3.00, where they are `in`
    /// and `out`.
    Es100Qualifier = "es100-qualifier",
    /// A GLSL ES 3.00 feature in a GLSL ES 1.00 shader: `in`/`out` variables, the `%`, bitwise
    /// and shift operators, uniform blocks, array constructors, initializers and `.length()`,
    /// `float[2]` array types, unsized arrays, `const` arrays.
    NotInEs100 = "not-in-es100",
    /// A name used as a type that is neither a built-in type nor a declared struct.
    UnknownType = "unknown-type",
    /// A function declared inside another function; GLSL ES declares functions at global
    /// scope only.
    NestedFunction = "nested-function",
    /// A method call other than `.length()`, the only method GLSL ES 3.00 has.
    MethodCall = "method-call",
    /// Expressions or statements nested more than 256 levels deep.
    NestingTooDeep = "nesting-too-deep",

    // ----- names and scopes (`check`) -----

    /// A name used as a variable that is not declared, or not in scope.
    UndeclaredIdentifier = "undeclared-identifier",
    /// A call of a function that is not declared (`texture2D` is GLSL ES 1.00).
    UndeclaredFunction = "undeclared-function",
    /// A name declared twice in the same scope.
    Redefinition = "redefinition",
    /// A name starting with `gl_`, or containing `__`, which GLSL ES reserves for built-ins
    /// (GLSL ES 3.00 §3.8).
    ReservedName = "reserved-name",
    /// A declaration, definition or overload of a built-in function's name, which GLSL ES 3.00
    /// forbids.
    BuiltinRedeclared = "builtin-redeclared",
    /// A call of something that is a variable, not a function (often a local hiding a
    /// function).
    NotAFunction = "not-a-function",
    /// A function's name used as a value.
    NotAValue = "not-a-value",
    /// A function declared again with a different return type.
    FunctionRedeclared = "function-redeclared",
    /// A function with the same parameter types defined twice.
    FunctionRedefined = "function-redefined",
    /// Functions that call each other in a cycle: GLSL ES 3.00 forbids recursion, even in
    /// functions that are never called.
    Recursion = "recursion",
    /// No `main` function, or `main` declared but never defined.
    MissingMain = "missing-main",
    /// `main` with parameters or a return type other than `void`.
    InvalidMain = "invalid-main",

    // ----- declarations and qualifiers (`check`) -----

    /// No precision for a type that needs one: a fragment shader has no default precision for
    /// `float`, and the 3D, array, shadow and integer samplers have none in either stage.
    MissingPrecision = "missing-precision",
    /// A precision qualifier on a type that takes none, such as `bool`.
    InvalidPrecision = "invalid-precision",
    /// A `precision` statement for a type other than `float`, `int` or a sampler type.
    InvalidPrecisionStatement = "invalid-precision-statement",
    /// The same kind of qualifier given twice (`in in`, `highp mediump`).
    DuplicateQualifier = "duplicate-qualifier",
    /// Qualifiers out of the order GLSL ES 3.00 requires: invariant, interpolation or layout,
    /// centroid, storage, precision.
    QualifierOrder = "qualifier-order",
    /// A storage qualifier where it cannot be: `in`/`out`/`uniform` on a local variable, or
    /// `inout` on a global one.
    InvalidStorage = "invalid-storage",
    /// A qualifier a return type or parameter cannot take (only a precision on a return type;
    /// `const` parameters only as `in`).
    InvalidQualifier = "invalid-qualifier",
    /// `flat`, `smooth` on something other than a vertex output or a fragment input.
    InvalidInterpolation = "invalid-interpolation",
    /// `centroid` on something other than a vertex output or a fragment input.
    InvalidCentroid = "invalid-centroid",
    /// `invariant` on something other than a vertex shader output.
    InvalidInvariant = "invalid-invariant",
    /// An `invariant NAME;` re-declaration inside a function; it must be at global scope.
    InvariantNotGlobal = "invariant-not-global",
    /// A layout qualifier where it does not apply, unknown, or without a valid value
    /// (`location` only on vertex inputs and fragment outputs, as a non-negative integer
    /// literal).
    InvalidLayout = "invalid-layout",
    /// A declaration with qualifiers but no type, other than `layout(...) uniform;`.
    InvalidDeclaration = "invalid-declaration",
    /// A warning: a declaration that declares nothing (`float;`).
    EmptyDeclaration = "empty-declaration",
    /// An initializer on a variable that cannot have one: a uniform, an input or an output.
    InvalidInitializer = "invalid-initializer",
    /// A `const` variable without an initializer.
    MissingInitializer = "missing-initializer",
    /// A `const` variable, or a global, whose initializer is not a constant expression.
    NonConstantInitializer = "non-constant-initializer",
    /// A shader input or output of a type it cannot have: a sampler or a `bool` anywhere; an
    /// array or struct as a vertex input; a matrix or struct as a fragment output; an array of
    /// structs, or a struct containing an array or a struct, as a varying.
    InvalidInterfaceType = "invalid-interface-type",
    /// An integer vertex output or fragment input without `flat`: integers cannot be
    /// interpolated.
    IntegerVaryingNotFlat = "integer-varying-not-flat",
    /// A sampler declared as something other than a uniform or a function parameter.
    SamplerNotUniform = "sampler-not-uniform",
    /// A function that returns a sampler.
    SamplerReturn = "sampler-return",
    /// A sampler as an `out` or `inout` parameter.
    SamplerOutParameter = "sampler-out-parameter",
    /// A parameter of type `void`.
    VoidParameter = "void-parameter",
    /// A variable or struct member of type `void`.
    VoidVariable = "void-variable",
    /// An array of `void`.
    VoidArray = "void-array",
    /// An array of arrays, which GLSL ES 3.00 does not have.
    ArrayOfArrays = "array-of-arrays",
    /// An array without a size where it needs one: a struct or block member, or a variable
    /// with no initializer to take it from.
    UnsizedArray = "unsized-array",
    /// An array size that is not a constant integral expression.
    NonConstantArraySize = "non-constant-array-size",
    /// An array size that is a constant but not an `int` or `uint`.
    ArraySizeType = "array-size-type",
    /// An array size of zero or less.
    ArraySize = "array-size",
    /// A struct with no members.
    EmptyStruct = "empty-struct",
    /// A struct defined inside another struct's member list, which GLSL ES 3.00 forbids.
    EmbeddedStruct = "embedded-struct",
    /// A struct member with a qualifier other than a precision.
    StructMemberQualifier = "struct-member-qualifier",
    /// An interface block that is not a uniform block (`in`/`out`/`buffer` blocks are not in
    /// GLSL ES 3.00), or a block or block member with a qualifier it cannot take.
    InvalidBlock = "invalid-block",
    /// A uniform block declared inside a function.
    BlockNotGlobal = "block-not-global",
    /// A sampler as a member of a uniform block.
    SamplerInBlock = "sampler-in-block",
    /// A `shared` or `packed` uniform block layout: WebGL2 allows only `std140`.
    WebglBlockLayout = "webgl-block-layout",
    /// Several fragment outputs, one of them without `layout(location = N)`: GLSL ES 3.00
    /// requires locations once there is more than one output.
    OutputLocationRequired = "output-location-required",
    /// Two fragment outputs at the same location.
    OutputLocationOverlap = "output-location-overlap",
    /// A variable larger than WebGL implementations accept for one variable (2 GiB laid out
    /// as a std140 member).
    VariableTooLarge = "variable-too-large",
    /// A local, global, constant, parameter or varying larger than the 64 KiB WebGL
    /// implementations accept for one private variable.
    PrivateVariableTooLarge = "private-variable-too-large",
    /// The shader's private variables together larger than the 16 MiB WebGL implementations
    /// accept.
    PrivateVariablesTooLarge = "private-variables-too-large",

    // ----- expressions and statements (`check`) -----

    /// Operands or an initializer of the wrong type: GLSL ES 3.00 has no implicit conversions
    /// (`float x = 1;`).
    TypeMismatch = "type-mismatch",
    /// No overload of a (built-in or declared) function takes the argument types given.
    NoMatchingOverload = "no-matching-overload",
    /// A constructor called with arguments it cannot take: none, too many or too few
    /// components, or of a type it cannot convert.
    InvalidConstructor = "invalid-constructor",
    /// A unary operator applied to a type it does not take (`!` on a float).
    InvalidOperand = "invalid-operand",
    /// A binary operator applied to types it does not take together (`vec2 + vec3`).
    InvalidOperands = "invalid-operands",
    /// A warning: a constant expression whose arithmetic gives a value that is not finite from
    /// operands that are: a result past the largest float (`1e38 * 10.0`, `1e38 / 1e-5`: ±∞),
    /// or NaN from infinities (`∞ / ∞`, `∞ - ∞`, `∞ * 0`). Chromium compiles the shader with
    /// that value.
    NonFiniteConstant = "non-finite-constant",
    /// A warning: `%` of a negative operand in a constant expression (`-7 % 3`): the result is
    /// undefined in GLSL ES, and Chromium compiles the shader with 0, the value ANGLE folds.
    NegativeModulus = "negative-modulus",
    /// A warning: a built-in function called with constant arguments for which GLSL ES leaves
    /// its result undefined (`sqrt(-1.0)`, `pow(-2.0, 2.0)`, `smoothstep(1.0, 0.0, 0.25)`,
    /// `normalize(vec3(0.0))`). Chromium compiles the shader with 0 for each such component,
    /// the value ANGLE folds.
    UndefinedConstantCall = "undefined-constant-call",
    /// A warning: a negative float constant converted to `uint` (`uint(-1.0)`), which GLSL ES
    /// leaves undefined. Chromium compiles the shader with the value converted through `int`
    /// (4294967295 for -1.0).
    NegativeToUint = "negative-to-uint",
    /// An assignment to something that cannot be written: a uniform, an input, a constant,
    /// a swizzle with a repeated component, or a value that is not an l-value.
    NotAssignable = "not-assignable",
    /// An assignment to a sampler.
    SamplerAssignment = "sampler-assignment",
    /// `?:` or `,` on arrays, structs containing arrays, or `void`: WebGL2 forbids them (WebGL 2.0
    /// §5.26).
    WebglForbiddenOperand = "webgl-forbidden-operand",
    /// Indexing of something that is not an array, matrix or vector (or a uniform block that
    /// is not an array).
    NotIndexable = "not-indexable",
    /// A constant index out of the bounds of an array, matrix or vector, or negative.
    IndexOutOfRange = "index-out-of-range",
    /// An array of samplers indexed with an expression that is not constant: GLSL ES 3.00
    /// does not allow selecting a sampler at run time.
    DynamicSamplerIndex = "dynamic-sampler-index",
    /// A fragment shader's output indexed with an expression that is not constant (`o[i]`): an
    /// array of outputs, or one output's vector components. GLSL ES 3.00 requires constant
    /// indices into output arrays, and Chromium refuses a run-time index into an output vector
    /// too.
    DynamicOutputIndex = "dynamic-output-index",
    /// A `while` or `for` loop that can never end: its condition is missing or always true (a
    /// constant, or a variable initialized to `true` that nothing writes) and nothing in it
    /// `break`s out of it or `return`s. Chromium refuses such a shader.
    InfiniteLoop = "infinite-loop",
    /// In a GLSL ES 1.00 shader for WebGL, an index that is not a constant-index-expression
    /// (constants and loop indices, Appendix A §5): only a vertex shader's uniforms may be
    /// indexed with anything else.
    NonConstantIndex = "non-constant-index",
    /// In a GLSL ES 1.00 shader for WebGL, a `while` or `do`-`while` loop, or a `for` loop whose
    /// header is not of the form Appendix A §4 requires: `for (int i = CONST; i OP CONST;
    /// i++)` (`i--`, `i += CONST`, `i -= CONST`, `++i`, `--i`), with an `int` or `float` index.
    UnsupportedLoop = "unsupported-loop",
    /// In a GLSL ES 1.00 shader for WebGL, a `for` loop's index assigned (or passed as an
    /// `out`/`inout` argument) inside the loop's body (Appendix A §4).
    LoopIndexAssigned = "loop-index-assigned",
    /// A GLSL ES 1.00 fragment shader that uses both `gl_FragColor` and `gl_FragData`
    /// (GLSL ES 1.00 §7.2).
    FragColorAndFragData = "frag-color-and-frag-data",
    /// A struct nested more than 4 levels deep, which WebGL forbids (WebGL 1.0 "Maximum Nesting
    /// of Structures in GLSL Shaders").
    StructNestingTooDeep = "struct-nesting-too-deep",
    /// A chain of function calls more than 256 deep from one function, which ANGLE refuses
    /// ("Call stack too deep").
    CallStackTooDeep = "call-stack-too-deep",
    /// A shader's uniforms, packed as GLSL ES 1.00 Appendix A §7 packs them, need more rows than
    /// the implementation's `MAX_VERTEX_UNIFORM_VECTORS` or `MAX_FRAGMENT_UNIFORM_VECTORS` (an
    /// error), or than WebGL guarantees (a warning).
    TooManyUniforms = "too-many-uniforms",
    /// An array of uniform blocks indexed with an expression that is not constant.
    DynamicBlockIndex = "dynamic-block-index",
    /// A field selection on a type that has no fields, such as an array (whose only member is
    /// `.length()`) or a scalar.
    InvalidField = "invalid-field",
    /// A struct member name that the struct does not have.
    NoSuchField = "no-such-field",
    /// A swizzle with a letter that is not a component, past the vector's size, or mixing the
    /// `xyzw`, `rgba` and `stpq` sets.
    InvalidSwizzle = "invalid-swizzle",
    /// `.length()` on something that is not an array.
    InvalidLength = "invalid-length",
    /// A texel offset argument that is not a constant expression.
    NonConstantOffset = "non-constant-offset",
    /// A constant texel offset outside the range WebGL2 guarantees (-8 to 7).
    TexelOffsetRange = "texel-offset-range",
    /// A built-in function available only in fragment shaders (`dFdx`, `dFdy`, `fwidth`, or
    /// a texture lookup with a bias argument) called in a vertex shader.
    FragmentOnlyBuiltin = "fragment-only-builtin",
    /// `discard` in a vertex shader.
    DiscardInVertex = "discard-in-vertex",
    /// `break` outside a loop or `switch`.
    BreakOutsideLoop = "break-outside-loop",
    /// `continue` outside a loop.
    ContinueOutsideLoop = "continue-outside-loop",
    /// A `case` or `default` label outside a `switch`.
    CaseOutsideSwitch = "case-outside-switch",
    /// A statement in a `switch` before its first `case` or `default` label.
    StatementBeforeCase = "statement-before-case",
    /// A `case` label that is not a constant integer expression.
    NonConstantCase = "non-constant-case",
    /// Two `case` labels of one `switch` with the same value.
    DuplicateCase = "duplicate-case",
    /// A `case` or `default` label with no statement after it before the end of the `switch`,
    /// which GLSL ES 3.00 forbids.
    LabelAtEndOfSwitch = "label-at-end-of-switch",
    /// `return;` without a value in a function that returns one.
    MissingReturnValue = "missing-return-value",
    /// `return` with a value in a `void` function.
    ReturnValueInVoid = "return-value-in-void",
    /// A non-`void` function with no `return` statement at all, which WebGL rejects.
    MissingReturn = "missing-return",

    // ----- linking (`link`) -----

    /// A fragment shader input with no vertex shader output of the same name.
    VaryingNotWritten = "varying-not-written",
    /// A vertex output and fragment input of one name with different types.
    VaryingTypeMismatch = "varying-type-mismatch",
    /// A vertex output and fragment input of one name, `flat` in one shader but not the other.
    VaryingInterpolationMismatch = "varying-interpolation-mismatch",
    /// The varyings, packed as GLSL ES 1.00 Appendix A §7 packs them (ANGLE does so for both
    /// versions), need more rows than the implementation's `MAX_VARYING_VECTORS` (an error) or
    /// than WebGL guarantees (a warning: 8 in WebGL 1, 15 in WebGL 2).
    TooManyVaryings = "too-many-varyings",
    /// A GLSL ES 1.00 shader linked with a GLSL ES 3.00 one: both shaders of a program must be
    /// of the same version.
    VersionMismatch = "version-mismatch",
    /// In GLSL ES 1.00, a varying (or `gl_Position` and `gl_FragCoord`, `gl_PointSize` and
    /// `gl_PointCoord`) `invariant` in one shader but not the other.
    InvariantMismatch = "invariant-mismatch",
    /// A uniform declared in both shaders with different types.
    UniformTypeMismatch = "uniform-type-mismatch",
    /// A uniform declared in both shaders with different precisions.
    UniformPrecisionMismatch = "uniform-precision-mismatch",
    /// A uniform block declared in both shaders with different member names or count.
    BlockMemberMismatch = "block-member-mismatch",
    /// A uniform block declared in both shaders with different member types.
    BlockTypeMismatch = "block-type-mismatch",
    /// A uniform block declared in both shaders with different layout qualifiers.
    BlockLayoutMismatch = "block-layout-mismatch",
    /// A uniform block declared in both shaders with different member precisions.
    BlockPrecisionMismatch = "block-precision-mismatch",
    /// Two vertex inputs at overlapping locations (from `layout(location)` or
    /// `bindAttribLocation`).
    AttributeLocationAlias = "attribute-location-alias",
    /// The vertex inputs need more locations than WebGL2 guarantees (16).
    TooManyAttributes = "too-many-attributes",

    // ----- the whole compile (`shader`) -----

    /// Valid GLSL ES 3.00 that essl cannot translate to naga IR yet.
    Unsupported = "unsupported",
    /// essl produced a naga module that naga rejects: a bug in essl.
    InternalError = "internal-error",
    /// More than 1,000 diagnostics: the rest are not shown (an error when an error was
    /// dropped, else a warning).
    TooManyDiagnostics = "too-many-diagnostics",
}

impl Code {
    /// The code's documentation as one paragraph per blank-line-separated block of its doc
    /// comment (the text `cargo doc` shows for the variant).
    pub fn doc(self) -> String {
        let mut out = String::new();
        for line in self.doc_lines() {
            out.push_str(line.strip_prefix(' ').unwrap_or(line));
            out.push('\n');
        }
        out
    }
}

impl fmt::Display for Code {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.as_str())
    }
}

/// The error of parsing a [`Code`] from a name that is not one.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct UnknownCode(pub String);

impl fmt::Display for UnknownCode {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "`{}` is not a diagnostic code of essl", self.0)
    }
}

impl std::error::Error for UnknownCode {}

impl FromStr for Code {
    type Err = UnknownCode;

    fn from_str(s: &str) -> Result<Code, UnknownCode> {
        Code::from_name(s).ok_or_else(|| UnknownCode(s.to_string()))
    }
}

#[cfg(test)]
mod tests {
    use super::Code;
    use std::collections::HashSet;

    #[test]
    fn names_round_trip() {
        for &code in Code::ALL {
            assert_eq!(Code::from_name(code.as_str()), Some(code));
            assert_eq!(code.as_str().parse::<Code>(), Ok(code));
            assert_eq!(code.to_string(), code.as_str());
        }
        assert_eq!(Code::from_name("no-such-code"), None);
        for &code in Code::ALL {
            assert!(
                !code.doc().trim().is_empty(),
                "`{code}` has no documentation"
            );
        }
        assert!(Code::UnterminatedComment
            .doc()
            .starts_with("A `/*` comment is never closed"));
        assert!("".parse::<Code>().is_err());
    }

    #[test]
    fn names_are_unique_and_kebab_case() {
        let mut seen = HashSet::new();
        for &code in Code::ALL {
            let name = code.as_str();
            assert!(seen.insert(name), "`{name}` is declared twice");
            assert!(
                !name.is_empty()
                    && !name.starts_with('-')
                    && !name.ends_with('-')
                    && !name.contains("--")
                    && name
                        .chars()
                        .all(|c| c.is_ascii_lowercase() || c.is_ascii_digit() || c == '-'),
                "`{name}` is not kebab-case"
            );
        }
        assert_eq!(seen.len(), Code::ALL.len());
    }
}
