//! Geometry wgpu cannot take as GL gives it, made on the CPU: topologies wgpu lacks
//! (`LINE_LOOP`, `TRIANGLE_FAN`, lists with primitive restart) become generated indices, and
//! attribute arrays at strides or offsets wgpu rejects are re-packed.

use crate::buffer::DerivedKey;

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
