//! Reading C arguments: fixed-length arrays, pname-sized vectors and name lists.
//!
//! Each function trusts a non-null pointer to hold what GL reads through it (the C caller's
//! promise) and turns NULL into "nothing there", which the command answers with its error.

/// `N` values at `p`; `None` for NULL.
pub unsafe fn array<T: Copy, const N: usize>(p: *const T) -> Option<[T; N]> {
    if p.is_null() {
        return None;
    }
    // SAFETY: a non-null pointer of a command taking N values points at N values (GL's
    // contract with the caller); read unaligned, as C may pass any address.
    Some(unsafe { p.cast::<[T; N]>().read_unaligned() })
}

/// The `count` values of a pname-dependent vector: empty for NULL or an unknown pname, which the
/// command then answers with INVALID_VALUE or INVALID_ENUM.
pub unsafe fn params<T: Copy>(p: *const T, count: Option<usize>) -> Vec<T> {
    match count {
        // SAFETY: as `slice`.
        Some(n) => unsafe { slice(p, n) }.to_vec(),
        None => Vec::new(),
    }
}

/// `n` object names (none for NULL or a negative `n`, which the command answers).
pub unsafe fn names(p: *const u32, n: i32) -> Vec<u32> {
    let n = usize::try_from(n).unwrap_or(0);
    // SAFETY: as `slice`.
    unsafe { slice(p, n) }.to_vec()
}

/// The `len` values at `p` as a slice; empty for NULL or a length no memory can have.
pub unsafe fn slice<'a, T>(p: *const T, len: usize) -> &'a [T] {
    let fits = len
        .checked_mul(std::mem::size_of::<T>())
        .is_some_and(|b| b <= isize::MAX as usize);
    if p.is_null() || len == 0 || !fits || p.align_offset(std::mem::align_of::<T>()) != 0 {
        return &[];
    }
    // SAFETY: non-null, aligned, and the caller's promise that `len` values live there.
    unsafe { std::slice::from_raw_parts(p, len) }
}

/// The `len` values at `p` to write into; empty for NULL or an impossible length.
pub unsafe fn slice_mut<'a, T>(p: *mut T, len: usize) -> &'a mut [T] {
    let fits = len
        .checked_mul(std::mem::size_of::<T>())
        .is_some_and(|b| b <= isize::MAX as usize);
    if p.is_null() || len == 0 || !fits || p.align_offset(std::mem::align_of::<T>()) != 0 {
        return &mut [];
    }
    // SAFETY: non-null, aligned, and the caller's promise that `len` values may be written.
    unsafe { std::slice::from_raw_parts_mut(p, len) }
}

/// `len` bytes at `p` (any alignment); empty for NULL.
pub unsafe fn bytes<'a>(p: *const std::ffi::c_void, len: usize) -> &'a [u8] {
    // SAFETY: as `slice`; bytes have no alignment.
    unsafe { slice(p.cast::<u8>(), len) }
}

/// `n` values when `n` is in 0..=`max` (none for NULL or another `n`: the command then answers
/// INVALID_VALUE without this reading past what a wrong size names).
pub unsafe fn values<T: Copy>(p: *const T, n: i32, max: usize) -> Vec<T> {
    let n = usize::try_from(n).ok().filter(|&n| n <= max).unwrap_or(0);
    // SAFETY: as `slice`.
    unsafe { slice(p, n) }.to_vec()
}

/// `n` integers (none for NULL or a negative `n`, which the command answers).
pub unsafe fn ints(p: *const i32, n: i32) -> Vec<i32> {
    let n = usize::try_from(n).unwrap_or(0);
    // SAFETY: as `slice`.
    unsafe { slice(p, n) }.to_vec()
}
