//! Large buffers backed by huge pages where the kernel allows it.
//!
//! A fresh allocation costs one page fault per 4 KiB on first touch; for the tens of megabytes
//! an edge table of a million-face mesh needs, those faults cost as much as the work itself.
//! Asking for transparent huge pages (as NumPy does for its large arrays) cuts them 512-fold.
//! Elsewhere, or when the kernel says no, this is an ordinary allocation.

/// Bytes above which a buffer is filled by every thread rather than one: first touch of fresh
/// memory (page faults and the kernel's zeroing) is slow enough to be worth sharing.
const PARALLEL_FILL: usize = 1 << 22;

/// A vector of `n` copies of `value` whose memory was advised for huge pages before it was
/// first touched.
pub fn filled_vec<T: Copy + Send + Sync>(n: usize, value: T) -> Vec<T> {
    use rayon::prelude::*;
    let mut v = with_capacity(n);
    if n * std::mem::size_of::<T>() < PARALLEL_FILL {
        v.resize(n, value);
        return v;
    }
    v.spare_capacity_mut()[..n]
        .par_chunks_mut((1 << 16) / std::mem::size_of::<T>().max(1))
        .for_each(|c| c.fill(std::mem::MaybeUninit::new(value)));
    // SAFETY: the first n elements were all written just above.
    unsafe { v.set_len(n) };
    v
}

/// An empty vector with room for `n` elements, advised for huge pages.
pub fn with_capacity<T>(n: usize) -> Vec<T> {
    let mut v: Vec<T> = Vec::with_capacity(n);
    advise_huge(v.as_mut_ptr() as *mut u8, n * std::mem::size_of::<T>());
    v
}

#[cfg(target_os = "linux")]
fn advise_huge(ptr: *mut u8, bytes: usize) {
    const HUGE: usize = 2 << 20;
    const MADV_HUGEPAGE: i32 = 14;
    extern "C" {
        fn madvise(addr: *mut std::ffi::c_void, len: usize, advice: i32) -> i32;
    }
    if bytes < 4 * HUGE {
        return;
    }
    // madvise wants a page-aligned start; advise the whole 2 MiB-aligned middle of the buffer.
    let start = (ptr as usize).next_multiple_of(HUGE);
    let end = (ptr as usize + bytes) / HUGE * HUGE;
    if end > start {
        // SAFETY: [start, end) lies inside the allocation; MADV_HUGEPAGE only changes how the
        // kernel backs those pages, never their contents. A failure (for example THP disabled)
        // is harmless and ignored.
        unsafe {
            madvise(start as *mut std::ffi::c_void, end - start, MADV_HUGEPAGE);
        }
    }
}

#[cfg(not(target_os = "linux"))]
fn advise_huge(_ptr: *mut u8, _bytes: usize) {}

#[cfg(test)]
mod tests {
    #[test]
    fn filled() {
        let v = super::filled_vec(10_000_000, 7u32);
        assert_eq!(v.len(), 10_000_000);
        assert!(v.iter().all(|&x| x == 7));
    }
}
