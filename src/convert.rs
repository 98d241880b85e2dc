//! The conversions between integer components and floats that GL applies to colours, normals and
//! normalized parameters: GL 2.1 table 2.9 (integer to float, §2.1.2) and table 4.9 (float to
//! integer, §4.3.2; also what `get_integerv` returns for a colour, §6.1.2). One copy of each
//! formula, for every place that converts: vertex attributes, array data, parameters, unpacked and
//! packed pixels, queries.

/// An unsigned component `c` of a type whose largest value is `max` (2^b − 1), as a float in
/// [0, 1]: c / (2^b − 1).
#[inline]
pub(crate) fn unsigned_to_unit(c: f64, max: f64) -> f64 {
    c / max
}

/// A signed component `c` of a b-bit type (`max` = 2^b − 1, the unsigned type's largest value),
/// as a float in [−1, 1]: (2c + 1) / (2^b − 1).
#[inline]
pub(crate) fn signed_to_unit(c: f64, max: f64) -> f64 {
    (2.0 * c + 1.0) / max
}

/// The inverse of [`signed_to_unit`]: ((2^b − 1)·f − 1) / 2, unrounded (callers round or
/// truncate as their section says, and saturate: outside [−1, 1] GL leaves the result undefined).
#[inline]
pub(crate) fn unit_to_signed(f: f64, max: f64) -> f64 {
    (max * f - 1.0) / 2.0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_extremes_map_to_the_unit_range() {
        let max = f64::from(u8::MAX);
        assert_eq!(signed_to_unit(127.0, max), 1.0);
        assert_eq!(signed_to_unit(-128.0, max), -1.0);
        assert_eq!(unsigned_to_unit(255.0, max), 1.0);
        assert_eq!(unit_to_signed(1.0, max), 127.0);
        assert_eq!(unit_to_signed(-1.0, max), -128.0);
        let max32 = f64::from(u32::MAX);
        assert_eq!(unit_to_signed(signed_to_unit(-5.0, max32), max32), -5.0);
    }
}
