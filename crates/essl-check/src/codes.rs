//! The diagnostics the pipeline itself reports, beside the front end's codes and the lint
//! rules: what goes wrong around a shader rather than in it (`essl explain CODE` prints
//! [`CheckCode::doc`]).

/// A diagnostic of the pipeline.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
#[non_exhaustive]
pub enum CheckCode {
    /// `#include "FILE"` names a file that no folder searched holds.
    IncludeNotFound,
    /// A file includes itself, directly or through others.
    IncludeCycle,
    /// `#include`s nest deeper than [`crate::include::MAX_DEPTH`] files.
    IncludeTooDeep,
    /// An included file exists but cannot be read.
    IncludeUnreadable,
    /// A preset's library could not be read (not installed, no Node.js).
    PresetUnavailable,
    /// A preset's library refused to assemble a program.
    PresetAssembly,
    /// A program a preset reads needs a value known only when the script runs.
    PresetUnchecked,
}

impl CheckCode {
    /// Every code.
    pub const ALL: &'static [CheckCode] = &[
        CheckCode::IncludeNotFound,
        CheckCode::IncludeCycle,
        CheckCode::IncludeTooDeep,
        CheckCode::IncludeUnreadable,
        CheckCode::PresetUnavailable,
        CheckCode::PresetAssembly,
        CheckCode::PresetUnchecked,
    ];

    /// The code's kebab-case name.
    pub fn as_str(self) -> &'static str {
        match self {
            CheckCode::IncludeNotFound => "include-not-found",
            CheckCode::IncludeCycle => "include-cycle",
            CheckCode::IncludeTooDeep => "include-too-deep",
            CheckCode::IncludeUnreadable => "include-unreadable",
            CheckCode::PresetUnavailable => "preset-unavailable",
            CheckCode::PresetAssembly => "preset-assembly",
            CheckCode::PresetUnchecked => "preset-unchecked",
        }
    }

    /// The code named `name`, if there is one.
    pub fn from_name(name: &str) -> Option<CheckCode> {
        CheckCode::ALL.iter().copied().find(|c| c.as_str() == name)
    }

    /// The code's documentation, as `essl explain` prints it.
    pub fn doc(self) -> &'static str {
        match self {
            CheckCode::IncludeNotFound => {
                "`#include \"FILE\"` names a file that is in neither the including file's \
                 folder nor an include folder.\n\n\
                 GLSL ES has no `#include`; essl follows it only where a project asks (`-I DIR`, \
                 `include = [...]` in essl.toml, a bundler plugin), searching the including \
                 file's own folder first, then each include folder in order. The shader is not \
                 compiled: without the included text, every name the file declares would be \
                 reported as undeclared.\n\n\
                 ```glsl\n#include \"lights.glsl\"   // error[include-not-found] where no folder holds it\n```\n"
            }
            CheckCode::IncludeCycle => {
                "A file includes itself, directly or through other files; the message names the \
                 chain.\n\nGuard the file with `#ifndef NAME` / `#define NAME` / `#endif`, or \
                 remove one of the `#include` lines.\n"
            }
            CheckCode::IncludeTooDeep => {
                "`#include`s nest deeper than 16 files: a bound on the work hostile input can \
                 cause (real projects nest a few levels).\n"
            }
            CheckCode::IncludeUnreadable => {
                "An included file exists but cannot be read: it is larger than 16 MiB, is not \
                 UTF-8, or may not be read.\n"
            }
            CheckCode::PresetUnavailable => {
                "A preset (`preset = \"luma\"` in essl.toml, `--preset`) reads the library it \
                 follows from the project's `node_modules`, with Node.js: the package is not \
                 installed at or above the file, or Node.js could not be started. The shaders \
                 are then checked as written, without what the library adds.\n"
            }
            CheckCode::PresetAssembly => {
                "The preset's library refused to assemble the program, as it would at run \
                 time: luma.gl throws for a shader whose first line is not `#version 300 es` \
                 (it drops that line), for an unknown module, or for a uniform block whose \
                 members are not in the order of the module's `uniformTypes`. The message is \
                 luma.gl's; for three.js, an `#include <chunk>` of a chunk it does not have.\n"
            }
            CheckCode::PresetUnchecked => {
                "A note: a program the preset reads is not checked, because a value it needs is \
                 known only when the script runs — a `defines` entry set from a variable \
                 (`defines: {KERNEL_RADIUS: kernelRadius}`), or a name the script replaces in \
                 the shader's text before compiling it (`.replace(/DEPTH_TO_VIEW_Z/g, …)`). Any \
                 value essl picked could report errors the page never has, or hide ones it has. \
                 Shown with `--show-notes`.\n"
            }
        }
    }
}
