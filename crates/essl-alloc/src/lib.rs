//! mimalloc as the global allocator of essl's binaries and benchmarks.
//!
//! The `mimalloc` crate's `MiMalloc` passes every layout to `mi_malloc_aligned`. In mimalloc 3
//! that call's fast path serves a block only when the size class's current page has a free block
//! at the right alignment; otherwise it falls to a generic path, which over-allocates (size plus
//! alignment) for every size class that is not a power of two. Over the first 600 dEQP shaders,
//! `essl lint --no-link` took that path 23,625 times (callgrind).
//!
//! [`Allocator`] does what Rust's own `System` allocator does on top of `malloc`: a layout whose
//! alignment is at most 16 bytes and at most its size goes to `mi_malloc`/`mi_realloc`, which
//! align every block of 16 bytes or more to 16 and every smaller one to its size class (a
//! multiple of the machine word). Other layouts keep the aligned calls. That is about 3 % fewer
//! instructions for `essl lint` than `MiMalloc` (docs/performance.md, "Allocator").
//!
//! It is a dozen lines on `libmimalloc-sys`, the crate under `mimalloc`, rather than a fork of
//! `mimalloc`: only the choice of call differs.

use std::alloc::{GlobalAlloc, Layout};
use std::ffi::c_void;

use libmimalloc_sys as mi;

/// The largest alignment `mi_malloc` gives every block of at least that size
/// (mimalloc's `MI_MAX_ALIGN_SIZE`).
const PLAIN_ALIGN: usize = 16;

/// mimalloc as a [`GlobalAlloc`], with the plain (unaligned) calls for ordinary layouts.
///
/// ```
/// #[global_allocator]
/// static ALLOCATOR: essl_alloc::Allocator = essl_alloc::Allocator;
/// ```
#[derive(Debug, Clone, Copy, Default)]
pub struct Allocator;

/// Whether `mi_malloc(size)` is aligned enough for `align`, as for `malloc` in `std`'s
/// `System`: the alignment is at most 16 and at most the size.
#[inline]
fn plain(align: usize, size: usize) -> bool {
    align <= PLAIN_ALIGN && align <= size
}

/// A block for `layout` from `plain_call` where [`plain`] allows it, else from `aligned_call`.
///
/// # Safety
/// Both calls must be mimalloc's allocation functions of those signatures.
#[inline(always)]
unsafe fn allocate(
    layout: Layout,
    plain_call: unsafe extern "C" fn(usize) -> *mut c_void,
    aligned_call: unsafe extern "C" fn(usize, usize) -> *mut c_void,
) -> *mut u8 {
    // SAFETY: the caller passes mimalloc's functions, which take any size and alignment.
    unsafe {
        if plain(layout.align(), layout.size()) {
            plain_call(layout.size()).cast()
        } else {
            aligned_call(layout.size(), layout.align()).cast()
        }
    }
}

// SAFETY: every pointer comes from mimalloc and goes back to it; `plain` sends a layout to the
// unaligned calls only where mimalloc's blocks already have its alignment (see the module doc),
// and the tests check that alignment for every size and alignment up to 4 KiB.
unsafe impl GlobalAlloc for Allocator {
    #[inline]
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: mimalloc's allocation calls accept any size and power-of-two alignment.
        unsafe { allocate(layout, mi::mi_malloc, mi::mi_malloc_aligned) }
    }

    #[inline]
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: as for `alloc`.
        unsafe { allocate(layout, mi::mi_zalloc, mi::mi_zalloc_aligned) }
    }

    #[inline]
    unsafe fn dealloc(&self, ptr: *mut u8, _layout: Layout) {
        // SAFETY: `ptr` came from this allocator, so from mimalloc, aligned or not.
        unsafe { mi::mi_free(ptr.cast::<c_void>()) }
    }

    #[inline]
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: `ptr` came from mimalloc; `mi_realloc` takes blocks from its aligned calls
        // too, and the new block is aligned as `plain` requires.
        unsafe {
            if plain(layout.align(), new_size) {
                mi::mi_realloc(ptr.cast::<c_void>(), new_size).cast()
            } else {
                mi::mi_realloc_aligned(ptr.cast::<c_void>(), new_size, layout.align()).cast()
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Allocates `size` bytes at `align`, fills them, and checks the alignment and the bytes
    /// through a reallocation to a larger and then a smaller size.
    fn round_trip(size: usize, align: usize, zeroed: bool) {
        let a = Allocator;
        let at = |size| Layout::from_size_align(size, align).unwrap();
        let aligned = |p: *mut u8, what: &str| {
            assert!(!p.is_null(), "{what}: null for size {size} align {align}");
            assert!(
                (p as usize).is_multiple_of(align),
                "{what}: size {size} align {align}"
            );
        };
        // SAFETY: each pointer is used within its layout's size and freed once, with it.
        unsafe {
            let p = if zeroed {
                a.alloc_zeroed(at(size))
            } else {
                a.alloc(at(size))
            };
            aligned(p, "alloc");
            if zeroed {
                assert!((0..size).all(|i| *p.add(i) == 0), "zeroed {size}");
            }
            p.write_bytes(0xa5, size);
            let (big, small) = (size * 2 + 8, size / 2 + 1);
            let q = a.realloc(p, at(size), big);
            aligned(q, "grow");
            assert!((0..size).all(|i| *q.add(i) == 0xa5), "grow {size}");
            q.write_bytes(0x5a, big);
            let r = a.realloc(q, at(big), small);
            aligned(r, "shrink");
            assert!((0..small).all(|i| *r.add(i) == 0x5a), "shrink {size}");
            a.dealloc(r, at(small));
        }
    }

    /// Every size up to 1 KiB, a sample up to 8 KiB and a few large ones, at every alignment
    /// up to 4 KiB: both sides of [`plain`], and both of mimalloc's small and large blocks.
    #[test]
    fn blocks_are_aligned_and_keep_their_bytes() {
        let sizes =
            (1..=1024)
                .chain((1032..=8192).step_by(40))
                .chain([65_536, 1 << 20, (1 << 22) + 24]);
        for size in sizes {
            for shift in 0..=12 {
                round_trip(size, 1 << shift, size % 3 == 0);
            }
        }
    }

    /// Many live blocks of one odd size class at once, so that pages fill and new ones start.
    #[test]
    fn a_full_size_class_stays_aligned() {
        let a = Allocator;
        let layout = Layout::from_size_align(48, 16).unwrap();
        // SAFETY: every block is freed once, with its layout.
        unsafe {
            let blocks: Vec<*mut u8> = (0..100_000).map(|_| a.alloc(layout)).collect();
            assert!(blocks
                .iter()
                .all(|p| !p.is_null() && (*p as usize).is_multiple_of(16)));
            for p in blocks {
                a.dealloc(p, layout);
            }
        }
    }
}
