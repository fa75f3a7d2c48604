//! The stack a compile needs, and running a pass on enough of it: the passes recurse over the
//! syntax tree, so each public entry point (compiling, linking, lowering a program) runs on a
//! stack of at least [`COMPILE_STACK`] bytes.

/// Stack that one compile (or link) may need. The passes recurse over the syntax tree, whose
/// depth the parser bounds at [`crate::parse::MAX_NESTING`], and the preprocessor over macro
/// calls nested in arguments (1,000 at most). The deepest inputs admitted need at most 1.5 MiB
/// in an optimised build (1,000 nested macro calls) and 5.1 MiB in an unoptimised one (256
/// nested loops), measured on x86-64 (`docs/reliability.md`); this is 2.7 and 2.3 times that.
pub const COMPILE_STACK: usize = if cfg!(debug_assertions) {
    12 << 20
} else {
    4 << 20
};

/// Runs `f` on the current thread when it has at least [`COMPILE_STACK`] bytes of stack left,
/// else on a fresh stack segment of that size (`stacker`, as rustc does). A program that
/// compiles many shaders keeps threads with enough stack (the main thread's 8 MiB, or the CLI's
/// workers), so the common path allocates nothing and starts no thread.
pub(crate) fn with_stack<T>(f: impl FnOnce() -> T) -> T {
    stacker::maybe_grow(COMPILE_STACK, COMPILE_STACK, f)
}
