//! GLSL names in the MSL, HLSL and desktop GLSL texts: the namer's suffixes undone where the
//! GLSL name is safe in the target.

use std::collections::{HashMap, HashSet};

use naga::proc::Namer;
use naga::{Handle, Module};

use super::{original_name, Tokens};

/// The MSL, HLSL or GLSL text with GLSL names given back, where naga's namer changed them
/// and the GLSL name is safe there: an identifier the target does not reserve (no reserved
/// prefix, no type name such as `float2`), appearing nowhere in the text. The names the
/// writer gave are found by running its namer's rules again (the suffixes: `_` after a final
/// digit, `_1` for a repeated name); a name the writer changed for a reason of its own (one
/// of its keywords) is not in the text as predicted, and stays.
pub fn restore_in(module: &Module, target: crate::Target, text: &str) -> String {
    let prefixes: &[&'static str] = match target {
        crate::Target::Glsl => &["gl_", "_group", "_immediates_binding_"],
        crate::Target::Msl => &[
            "clamped_lod_e",
            "ray_query_get_intersection",
            "naga_query_init_tracker_for_",
        ],
        _ => &["__dynamic_buffer_offsets", "_naga", "naga_"],
    };
    let mut names = naga::FastHashMap::default();
    Namer::default().reset(
        module,
        naga::proc::KeywordSet::empty(),
        naga::proc::KeywordSet::empty(),
        naga::proc::CaseInsensitiveKeywordSet::empty(),
        prefixes,
        &mut names,
    );
    let mut function_index: HashMap<Handle<naga::Function>, usize> = HashMap::new();
    for (i, (h, _)) in module.functions.iter().enumerate() {
        function_index.insert(h, i);
    }
    let ep_base = module.functions.len();
    let mut meanings: HashMap<String, HashSet<String>> = HashMap::new();
    let mut items: Vec<(String, String)> = Vec::new();
    for (key, emitted) in &names {
        let Some((_, original)) = original_name(module, key, &function_index, ep_base) else {
            continue;
        };
        meanings
            .entry(emitted.clone())
            .or_default()
            .insert(original.clone());
        if *emitted != original {
            items.push((emitted.clone(), original));
        }
    }
    items.sort();
    items.dedup();
    let mut tokens = Tokens::new(text);
    let all = 0..tokens.len();
    for (emitted, original) in items {
        let suffix = emitted.strip_prefix(original.as_str()).unwrap_or("");
        let namer_suffix = suffix == "_"
            || suffix
                .strip_prefix('_')
                .is_some_and(|d| !d.is_empty() && d.bytes().all(|b| b.is_ascii_digit()));
        if !namer_suffix
            || !safe_in(&original, prefixes)
            || meanings.get(&emitted).is_some_and(|m| m.len() > 1)
            || tokens.any(all.clone(), &original)
            || !tokens.any(all.clone(), &emitted)
        {
            continue;
        }
        tokens.rename(all.clone(), &emitted, &original);
    }
    tokens.text()
}

/// Whether a GLSL name is an identifier that MSL, HLSL or desktop GLSL takes as it is.
fn safe_in(name: &str, prefixes: &[&str]) -> bool {
    let ident = name.starts_with(|c: char| c.is_ascii_alphabetic())
        && name.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
        && !name.contains("__");
    if !ident || name.starts_with("gl_") || prefixes.iter().any(|p| name.starts_with(p)) {
        return false;
    }
    // Type names with a size (`float2`, `half4x4`, `dvec3`, `sampler2D`, `image2D`…), which
    // a GLSL ES shader may use as names and these languages reserve.
    let lower = name.to_ascii_lowercase();
    let sized = lower.contains(|c: char| c.is_ascii_digit());
    const STEMS: &[&str] = &[
        "bool",
        "char",
        "uchar",
        "short",
        "ushort",
        "int",
        "uint",
        "long",
        "ulong",
        "half",
        "float",
        "double",
        "min16float",
        "min10float",
        "min16int",
        "min12int",
        "min16uint",
        "int8_t",
        "int16_t",
        "int32_t",
        "int64_t",
        "uint8_t",
        "uint16_t",
        "uint32_t",
        "uint64_t",
        "float16_t",
        "float32_t",
        "float64_t",
        "dword",
        "matrix",
        "vector",
        "vec",
        "bvec",
        "ivec",
        "uvec",
        "dvec",
        "mat",
        "dmat",
        "f16vec",
        "f32vec",
        "f64vec",
        "i8vec",
        "i16vec",
        "i32vec",
        "i64vec",
        "u8vec",
        "u16vec",
        "u32vec",
        "u64vec",
        "f16mat",
        "f32mat",
        "f64mat",
        "packed_float",
        "packed_half",
        "packed_int",
        "packed_uint",
        "packed_short",
        "packed_ushort",
        "packed_char",
        "packed_uchar",
        "packed_bool",
        "simd_float",
        "texture",
        "sampler",
        "image",
        "isampler",
        "usampler",
        "iimage",
        "uimage",
        "itexture",
        "utexture",
        "rwtexture",
        "texture1d",
        "texture2d",
        "texture3d",
    ];
    let reserved_type = sized && STEMS.iter().any(|s| lower.starts_with(s));
    !reserved_type
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sized_type_names_are_not_given_back() {
        assert!(safe_in("u_light0", &[]));
        assert!(safe_in("v_uv0", &[]));
        assert!(!safe_in("float2", &[]));
        assert!(!safe_in("half4x4", &[]));
        assert!(!safe_in("dvec3", &[]));
        assert!(!safe_in("gl_thing", &[]));
        assert!(!safe_in("_x1", &[]));
        assert!(!safe_in("naga_x", &["naga_"]));
    }
}
