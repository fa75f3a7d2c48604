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
//! Blocks of [`LARGE`] bytes or more come from the system allocator instead. mimalloc keeps
//! the memory of a freed block committed for a while (its purge delay) to serve the next
//! allocations quickly; a 1 MiB shader's token, syntax-tree and checked-tree vectors, each tens
//! of MiB and each freed before the next pass's is at its largest, then all count in the
//! process's resident memory: 280 MiB for 350,000 statements naming an undeclared variable,
//! against 109 MiB on glibc's `malloc`, which unmaps such blocks when they are freed and grows
//! them with `mremap` (docs/reliability.md). No ordinary shader allocates a block that large.
//!
//! It is a few dozen lines on `libmimalloc-sys`, the crate under `mimalloc`, rather than a fork
//! of `mimalloc`: only the choice of call differs.

use std::alloc::{GlobalAlloc, Layout, System};
use std::ffi::c_void;

use libmimalloc_sys as mi;

/// The largest alignment `mi_malloc` gives every block of at least that size
/// (mimalloc's `MI_MAX_ALIGN_SIZE`).
const PLAIN_ALIGN: usize = 16;

/// The size from which a block comes from [`System`] rather than mimalloc (1 MiB).
pub const LARGE: usize = 1 << 20;

/// Whether a block of `size` bytes is [`System`]'s.
#[inline]
fn large(size: usize) -> bool {
    size >= LARGE
}

// The calls for large blocks, out of line: the test for them stays one comparison in front of
// mimalloc's tail calls.

/// # Safety
/// As [`GlobalAlloc::alloc`].
#[cold]
#[inline(never)]
unsafe fn large_alloc(layout: Layout, zeroed: bool) -> *mut u8 {
    // SAFETY: the caller's layout has a non-zero size, as `GlobalAlloc::alloc` requires.
    unsafe {
        if zeroed {
            System.alloc_zeroed(layout)
        } else {
            System.alloc(layout)
        }
    }
}

/// # Safety
/// As [`GlobalAlloc::dealloc`], for a block [`System`] gave.
#[cold]
#[inline(never)]
unsafe fn large_dealloc(ptr: *mut u8, layout: Layout) {
    // SAFETY: a block of this size came from `System`, with this layout.
    unsafe { System.dealloc(ptr, layout) }
}

/// # Safety
/// As [`GlobalAlloc::realloc`], where the old or the new size is [`LARGE`].
#[cold]
#[inline(never)]
unsafe fn large_realloc(ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
    // SAFETY: `ptr` came from `System` with `layout` when that size is large; `new_size` is
    // non-zero and, rounded up to the alignment, fits in `isize` (the caller's duty).
    unsafe {
        if large(layout.size()) && large(new_size) {
            return System.realloc(ptr, layout, new_size);
        }
        // The block moves to the other allocator: a new block, the bytes both sizes hold, and
        // the old block freed where it came from.
        let new_layout = Layout::from_size_align_unchecked(new_size, layout.align());
        let new = Allocator.alloc(new_layout);
        if !new.is_null() {
            std::ptr::copy_nonoverlapping(ptr, new, layout.size().min(new_size));
            Allocator.dealloc(ptr, layout);
        }
        new
    }
}

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

// SAFETY: a block's size says whose it is — `GlobalAlloc` gives `dealloc` and `realloc` the
// layout the block was allocated (or last reallocated) with — and every pointer goes back to
// the allocator that gave it: [`System`] for [`LARGE`] sizes, mimalloc for the others. `plain`
// sends a layout to mimalloc's unaligned calls only where its blocks already have that
// alignment (see the module doc); the tests check the alignment for every size and alignment
// up to 4 KiB, and blocks that move between the two allocators.
unsafe impl GlobalAlloc for Allocator {
    #[inline]
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        // SAFETY: `GlobalAlloc::alloc`'s contract is the callee's; mimalloc's allocation calls
        // accept any size and power-of-two alignment.
        unsafe {
            if large(layout.size()) {
                large_alloc(layout, false)
            } else {
                allocate(layout, mi::mi_malloc, mi::mi_malloc_aligned)
            }
        }
    }

    #[inline]
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        // SAFETY: as for `alloc`.
        unsafe {
            if large(layout.size()) {
                large_alloc(layout, true)
            } else {
                allocate(layout, mi::mi_zalloc, mi::mi_zalloc_aligned)
            }
        }
    }

    #[inline]
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        // SAFETY: a large block came from `System` with this layout; a smaller one from
        // mimalloc, aligned or not.
        unsafe {
            if large(layout.size()) {
                large_dealloc(ptr, layout)
            } else {
                mi::mi_free(ptr.cast::<c_void>())
            }
        }
    }

    #[inline]
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        // SAFETY: `ptr` came from this allocator with `layout`: from mimalloc when neither size
        // is large, where `mi_realloc` takes blocks from its aligned calls too and the new
        // block is aligned as `plain` requires.
        unsafe {
            if large(layout.size()) || large(new_size) {
                large_realloc(ptr, layout, new_size)
            } else if plain(layout.align(), new_size) {
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
    /// up to 4 KiB: both sides of [`plain`], both of mimalloc's small and large blocks, and
    /// blocks that grow into [`LARGE`] and shrink out of it (`round_trip` doubles, then halves).
    #[test]
    fn blocks_are_aligned_and_keep_their_bytes() {
        let sizes = (1..=1024).chain((1032..=8192).step_by(40)).chain([
            65_536,
            LARGE / 2 - 4,
            LARGE - 1,
            LARGE,
            LARGE + 24,
            (1 << 22) + 24,
        ]);
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
