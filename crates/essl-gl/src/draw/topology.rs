//! Geometry wgpu cannot take as GL gives it, made on the CPU: topologies wgpu lacks
//! (`LINE_LOOP`, `TRIANGLE_FAN`, lists with primitive restart) become generated indices, and
//! attribute arrays at strides or offsets wgpu rejects are re-packed.

use crate::buffer::DerivedKey;
use crate::gl;

/// A topology wgpu lacks, drawn as another one with generated indices.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Emulated {
    None,
    /// `LINE_LOOP` as a line strip that returns to its first vertex.
    LineLoop,
    /// `TRIANGLE_FAN` as a triangle list.
    TriangleFan,
    /// A list (of primitives of this many vertices) whose indices hold the restart index:
    /// Vulkan restarts only strips, so the restarts are applied to the indices, dropping
    /// incomplete primitives as GL does.
    List(usize),
}

/// The size in bytes of an index of type `ty`, or `None` for a type that is not one.
pub(super) fn index_size(ty: u32) -> Option<u64> {
    match ty {
        gl::UNSIGNED_BYTE => Some(1),
        gl::UNSIGNED_SHORT => Some(2),
        gl::UNSIGNED_INT => Some(4),
        _ => None,
    }
}

/// Index `i` of `count` indices of type `ty` at `offset`, as `u32` (`u32::MAX` for the
/// primitive restart index, which WebGL2 always enables).
pub(super) fn read_indices(
    data: &[u8],
    ty: u32,
    offset: u64,
    count: u64,
) -> impl Iterator<Item = u32> + '_ {
    let size = index_size(ty).unwrap_or(4) as usize;
    let start = offset as usize;
    data[start..start + count as usize * size]
        .chunks_exact(size)
        .map(move |c| match size {
            1 => {
                if c[0] == 0xFF {
                    u32::MAX
                } else {
                    c[0] as u32
                }
            }
            2 => {
                let v = u16::from_ne_bytes([c[0], c[1]]);
                if v == 0xFFFF {
                    u32::MAX
                } else {
                    v as u32
                }
            }
            _ => u32::from_ne_bytes([c[0], c[1], c[2], c[3]]),
        })
}

/// Generated indices for an emulated topology over `indices` (restart splits primitives).
pub(super) fn emulate(indices: impl Iterator<Item = u32>, how: Emulated) -> Vec<u32> {
    let mut out = Vec::new();
    let mut segment: Vec<u32> = Vec::new();
    let flush = |segment: &mut Vec<u32>, out: &mut Vec<u32>| {
        match how {
            Emulated::LineLoop if segment.len() >= 2 => {
                if !out.is_empty() {
                    out.push(u32::MAX);
                }
                out.extend_from_slice(segment);
                out.push(segment[0]);
            }
            Emulated::List(n) => {
                let keep = segment.len() / n * n;
                out.extend_from_slice(&segment[..keep]);
            }
            Emulated::TriangleFan if segment.len() >= 3 => {
                for i in 1..segment.len() - 1 {
                    out.extend_from_slice(&[segment[0], segment[i], segment[i + 1]]);
                }
            }
            _ => {}
        }
        segment.clear();
    };
    for i in indices {
        if i == u32::MAX {
            flush(&mut segment, &mut out);
        } else {
            segment.push(i);
        }
    }
    flush(&mut segment, &mut out);
    out
}

/// Re-packs one attribute's elements at a stride wgpu accepts.
pub(super) fn repack(data: &[u8], key: &DerivedKey) -> Vec<u8> {
    let DerivedKey::Repacked {
        offset,
        stride,
        element,
        packed,
        per_instance,
    } = *key
    else {
        return Vec::new();
    };
    let (offset, stride, element, packed) = (
        offset as usize,
        stride as usize,
        element as usize,
        packed as usize,
    );
    let available = if data.len() >= offset + element {
        (data.len() - offset - element) / stride + 1
    } else {
        0
    };
    let (count, source): (usize, Box<dyn Fn(usize) -> usize>) = match per_instance {
        Some((divisor, instances)) => (instances as usize, Box::new(move |i| i / divisor as usize)),
        None => (available, Box::new(|i| i)),
    };
    let mut out = vec![0u8; count * packed];
    for i in 0..count {
        let s = source(i);
        if s < available {
            let at = offset + s * stride;
            out[i * packed..i * packed + element].copy_from_slice(&data[at..at + element]);
        }
    }
    out
}
