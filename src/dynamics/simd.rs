//! Lane vectors for the lock-step RK4 kernels, and the instruction set
//! chosen at run time.
//!
//! A kernel is written once, generic over [`Simd`] (a value holding one
//! `f64` per lane); it is instantiated with plain `f64` (one lane), with
//! portable arrays, and on x86-64 with SSE2 (2 lanes), AVX2 (4 lanes, or 8
//! as two interleaved vectors) and AVX-512F (8 lanes) registers. The x86
//! instantiations run inside `#[target_feature]` functions entered only
//! after `is_x86_feature_detected!` confirmed the instruction set.
//!
//! Every operation is a single IEEE-754 operation with the same rounding in
//! every instantiation (add, sub, mul, compare/select, min/max against zero):
//! no fused multiply-add, no reassociation. A lane therefore gives bitwise
//! the same result in every instantiation and on every CPU, whatever lanes it
//! is grouped with (tested in `batch.rs`).

#[cfg(target_arch = "x86_64")]
use std::arch::x86_64::*;

/// One `f64` per lane with the operations the kernels use.
pub trait Simd: Copy {
    /// Every lane `v`.
    fn splat(v: f64) -> Self;
    /// Lane-wise `self + o`.
    fn add(self, o: Self) -> Self;
    /// Lane-wise `self - o`.
    fn sub(self, o: Self) -> Self;
    /// Lane-wise `self * o`.
    fn mul(self, o: Self) -> Self;
    /// Lane-wise `max(0, self)`: `self` unless `0 > self` (NaN stays NaN).
    fn pos_part(self) -> Self;
    /// Lane-wise `min(0, self)`: `self` unless `0 < self` (NaN stays NaN).
    fn neg_part(self) -> Self;
    /// Lane-wise: `a` where `self != 0` (or NaN), else `b`.
    fn select_nonzero(self, a: Self, b: Self) -> Self;
    /// Lane-wise `self` if `self < o`, else `o` (`f64::min` for numbers).
    fn min(self, o: Self) -> Self;
    /// Lane-wise `self` if `self > o`, else `o` (`f64::max` for numbers).
    fn max(self, o: Self) -> Self;
}

/// A [`Simd`] value with exactly `L` lanes, loaded from / stored to `[f64; L]`.
pub trait Lanes<const L: usize>: Simd {
    /// Load lanes.
    fn load(p: &[f64; L]) -> Self;
    /// Store lanes.
    fn store(self, p: &mut [f64; L]);
}

impl Simd for f64 {
    #[inline(always)]
    fn splat(v: f64) -> Self {
        v
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        self + o
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        self - o
    }
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        self * o
    }
    #[inline(always)]
    fn pos_part(self) -> Self {
        if 0.0 > self {
            0.0
        } else {
            self
        }
    }
    #[inline(always)]
    fn neg_part(self) -> Self {
        if 0.0 < self {
            0.0
        } else {
            self
        }
    }
    #[inline(always)]
    fn select_nonzero(self, a: Self, b: Self) -> Self {
        if self != 0.0 {
            a
        } else {
            b
        }
    }
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        if self < o {
            self
        } else {
            o
        }
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        if self > o {
            self
        } else {
            o
        }
    }
}

impl<const L: usize> Lanes<L> for f64 {
    #[inline(always)]
    fn load(p: &[f64; L]) -> Self {
        assert!(L == 1, "f64 holds 1 lane");
        p[0]
    }
    #[inline(always)]
    fn store(self, p: &mut [f64; L]) {
        assert!(L == 1, "f64 holds 1 lane");
        p[0] = self;
    }
}

/// Portable lanes: an array, each element through the `f64` operations
/// (the compiler vectorises the loops for the target's baseline).
#[derive(Clone, Copy, Debug)]
pub struct Portable<const L: usize>(pub [f64; L]);

impl<const L: usize> Portable<L> {
    #[inline(always)]
    fn zip(self, o: Self, f: impl Fn(f64, f64) -> f64) -> Self {
        Portable(std::array::from_fn(|l| f(self.0[l], o.0[l])))
    }
}

impl<const L: usize> Simd for Portable<L> {
    #[inline(always)]
    fn splat(v: f64) -> Self {
        Portable([v; L])
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        self.zip(o, |a, b| a + b)
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        self.zip(o, |a, b| a - b)
    }
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        self.zip(o, |a, b| a * b)
    }
    #[inline(always)]
    fn pos_part(self) -> Self {
        Portable(self.0.map(Simd::pos_part))
    }
    #[inline(always)]
    fn neg_part(self) -> Self {
        Portable(self.0.map(Simd::neg_part))
    }
    #[inline(always)]
    fn select_nonzero(self, a: Self, b: Self) -> Self {
        Portable(std::array::from_fn(|l| self.0[l].select_nonzero(a.0[l], b.0[l])))
    }
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        self.zip(o, Simd::min)
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        self.zip(o, Simd::max)
    }
}

impl<const L: usize> Lanes<L> for Portable<L> {
    #[inline(always)]
    fn load(p: &[f64; L]) -> Self {
        Portable(*p)
    }
    #[inline(always)]
    fn store(self, p: &mut [f64; L]) {
        *p = self.0;
    }
}

/// Instruction set of the lane kernels.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Isa {
    /// Portable code (the target's baseline vector unit, e.g. SSE2 or NEON).
    Portable,
    /// x86-64 AVX2: 4 lanes per register, 8-lane batches as two registers.
    Avx2,
    /// x86-64 AVX-512F: 8 lanes per register.
    Avx512,
}

impl Isa {
    /// Whether this CPU can run the instruction set.
    pub fn is_available(self) -> bool {
        match self {
            Isa::Portable => true,
            #[cfg(target_arch = "x86_64")]
            Isa::Avx2 => std::arch::is_x86_feature_detected!("avx2"),
            #[cfg(target_arch = "x86_64")]
            Isa::Avx512 => {
                std::arch::is_x86_feature_detected!("avx512f") && std::arch::is_x86_feature_detected!("avx2")
            }
            #[cfg(not(target_arch = "x86_64"))]
            _ => false,
        }
    }

    /// The best instruction set this CPU supports (detected once).
    pub fn detected() -> Isa {
        static BEST: std::sync::OnceLock<Isa> = std::sync::OnceLock::new();
        *BEST.get_or_init(|| {
            [Isa::Avx512, Isa::Avx2]
                .into_iter()
                .find(|i| i.is_available())
                .unwrap_or(Isa::Portable)
        })
    }

    /// Every instruction set this CPU supports, best last.
    pub fn available() -> Vec<Isa> {
        [Isa::Portable, Isa::Avx2, Isa::Avx512]
            .into_iter()
            .filter(|i| i.is_available())
            .collect()
    }

    /// Widest lock-step batch worth running on this instruction set: 8 with
    /// AVX-512 (one register), 4 otherwise (two chains of AVX2 registers
    /// or portable arrays run out of registers).
    pub fn max_lanes(self) -> usize {
        match self {
            Isa::Avx512 => 8,
            Isa::Avx2 | Isa::Portable => 4,
        }
    }

    /// Lower-case name (`"portable"`, `"avx2"`, `"avx512"`).
    pub fn name(self) -> &'static str {
        match self {
            Isa::Portable => "portable",
            Isa::Avx2 => "avx2",
            Isa::Avx512 => "avx512",
        }
    }
}

// ------------------------------------------------------------- x86-64 ----
//
// The wrappers below are `#[inline(always)]` functions without target
// features: they are only instantiated inside the `#[target_feature]`
// entry points of `batch.rs` (reached after run-time detection), where they
// and the intrinsics inline into AVX2 / AVX-512 code. `L` is the lane count
// of the batch; each type is used only with its own lane count (checked).

/// SSE2 (x86-64 baseline): 2 lanes.
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy, Debug)]
pub struct Sse2(__m128d);

#[cfg(target_arch = "x86_64")]
impl Simd for Sse2 {
    #[inline(always)]
    fn splat(v: f64) -> Self {
        // SAFETY (all Sse2 methods): SSE2 is part of the x86-64 baseline.
        Sse2(unsafe { _mm_set1_pd(v) })
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Sse2(unsafe { _mm_add_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Sse2(unsafe { _mm_sub_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        Sse2(unsafe { _mm_mul_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn pos_part(self) -> Self {
        // maxpd(a, b) = a > b ? a : b, so (0, x) keeps x unless 0 > x.
        Sse2(unsafe { _mm_max_pd(_mm_setzero_pd(), self.0) })
    }
    #[inline(always)]
    fn neg_part(self) -> Self {
        Sse2(unsafe { _mm_min_pd(_mm_setzero_pd(), self.0) })
    }
    #[inline(always)]
    fn select_nonzero(self, a: Self, b: Self) -> Self {
        // cmpneqpd is true for NaN (unordered), as `!=`.
        Sse2(unsafe {
            let m = _mm_cmpneq_pd(self.0, _mm_setzero_pd());
            _mm_or_pd(_mm_and_pd(m, a.0), _mm_andnot_pd(m, b.0))
        })
    }
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        Sse2(unsafe { _mm_min_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        Sse2(unsafe { _mm_max_pd(self.0, o.0) })
    }
}

#[cfg(target_arch = "x86_64")]
impl<const L: usize> Lanes<L> for Sse2 {
    #[inline(always)]
    fn load(p: &[f64; L]) -> Self {
        assert!(L == 2, "Sse2 holds 2 lanes");
        // SAFETY: reads the 2 f64 of `p` (unaligned load).
        Sse2(unsafe { _mm_loadu_pd(p.as_ptr()) })
    }
    #[inline(always)]
    fn store(self, p: &mut [f64; L]) {
        assert!(L == 2, "Sse2 holds 2 lanes");
        // SAFETY: writes the 2 f64 of `p` (unaligned store).
        unsafe { _mm_storeu_pd(p.as_mut_ptr(), self.0) }
    }
}

/// AVX2: 4 lanes. Only constructed inside `#[target_feature(enable = "avx2")]`
/// code (see `batch.rs`).
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy, Debug)]
pub struct Avx4(__m256d);

#[cfg(target_arch = "x86_64")]
impl Simd for Avx4 {
    #[inline(always)]
    fn splat(v: f64) -> Self {
        // SAFETY (all Avx4 methods): AVX2 was detected before any Avx4 exists.
        Avx4(unsafe { _mm256_set1_pd(v) })
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Avx4(unsafe { _mm256_add_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Avx4(unsafe { _mm256_sub_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        Avx4(unsafe { _mm256_mul_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn pos_part(self) -> Self {
        Avx4(unsafe { _mm256_max_pd(_mm256_setzero_pd(), self.0) })
    }
    #[inline(always)]
    fn neg_part(self) -> Self {
        Avx4(unsafe { _mm256_min_pd(_mm256_setzero_pd(), self.0) })
    }
    #[inline(always)]
    fn select_nonzero(self, a: Self, b: Self) -> Self {
        Avx4(unsafe {
            let m = _mm256_cmp_pd::<_CMP_NEQ_UQ>(self.0, _mm256_setzero_pd());
            _mm256_blendv_pd(b.0, a.0, m)
        })
    }
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        Avx4(unsafe { _mm256_min_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        Avx4(unsafe { _mm256_max_pd(self.0, o.0) })
    }
}

#[cfg(target_arch = "x86_64")]
impl<const L: usize> Lanes<L> for Avx4 {
    #[inline(always)]
    fn load(p: &[f64; L]) -> Self {
        assert!(L == 4, "Avx4 holds 4 lanes");
        // SAFETY: reads the 4 f64 of `p`; AVX2 detected (see type docs).
        Avx4(unsafe { _mm256_loadu_pd(p.as_ptr()) })
    }
    #[inline(always)]
    fn store(self, p: &mut [f64; L]) {
        assert!(L == 4, "Avx4 holds 4 lanes");
        // SAFETY: writes the 4 f64 of `p`; AVX2 detected.
        unsafe { _mm256_storeu_pd(p.as_mut_ptr(), self.0) }
    }
}

/// AVX2, 8 lanes as two registers (two independent dependency chains).
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy, Debug)]
pub struct Avx8(Avx4, Avx4);

#[cfg(target_arch = "x86_64")]
impl Simd for Avx8 {
    #[inline(always)]
    fn splat(v: f64) -> Self {
        Avx8(Avx4::splat(v), Avx4::splat(v))
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Avx8(self.0.add(o.0), self.1.add(o.1))
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Avx8(self.0.sub(o.0), self.1.sub(o.1))
    }
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        Avx8(self.0.mul(o.0), self.1.mul(o.1))
    }
    #[inline(always)]
    fn pos_part(self) -> Self {
        Avx8(self.0.pos_part(), self.1.pos_part())
    }
    #[inline(always)]
    fn neg_part(self) -> Self {
        Avx8(self.0.neg_part(), self.1.neg_part())
    }
    #[inline(always)]
    fn select_nonzero(self, a: Self, b: Self) -> Self {
        Avx8(self.0.select_nonzero(a.0, b.0), self.1.select_nonzero(a.1, b.1))
    }
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        Avx8(self.0.min(o.0), self.1.min(o.1))
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        Avx8(self.0.max(o.0), self.1.max(o.1))
    }
}

#[cfg(target_arch = "x86_64")]
impl<const L: usize> Lanes<L> for Avx8 {
    #[inline(always)]
    fn load(p: &[f64; L]) -> Self {
        assert!(L == 8, "Avx8 holds 8 lanes");
        // SAFETY: reads the 8 f64 of `p`; AVX2 detected.
        unsafe {
            Avx8(
                Avx4(_mm256_loadu_pd(p.as_ptr())),
                Avx4(_mm256_loadu_pd(p.as_ptr().add(4))),
            )
        }
    }
    #[inline(always)]
    fn store(self, p: &mut [f64; L]) {
        assert!(L == 8, "Avx8 holds 8 lanes");
        // SAFETY: writes the 8 f64 of `p`; AVX2 detected.
        unsafe {
            _mm256_storeu_pd(p.as_mut_ptr(), self.0 .0);
            _mm256_storeu_pd(p.as_mut_ptr().add(4), self.1 .0);
        }
    }
}

/// AVX-512F: 8 lanes. Only constructed inside
/// `#[target_feature(enable = "avx512f")]` code (see `batch.rs`).
#[cfg(target_arch = "x86_64")]
#[derive(Clone, Copy, Debug)]
pub struct Avx512(__m512d);

#[cfg(target_arch = "x86_64")]
impl Simd for Avx512 {
    #[inline(always)]
    fn splat(v: f64) -> Self {
        // SAFETY (all Avx512 methods): AVX-512F was detected before any
        // Avx512 exists.
        Avx512(unsafe { _mm512_set1_pd(v) })
    }
    #[inline(always)]
    fn add(self, o: Self) -> Self {
        Avx512(unsafe { _mm512_add_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn sub(self, o: Self) -> Self {
        Avx512(unsafe { _mm512_sub_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn mul(self, o: Self) -> Self {
        Avx512(unsafe { _mm512_mul_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn pos_part(self) -> Self {
        Avx512(unsafe { _mm512_max_pd(_mm512_setzero_pd(), self.0) })
    }
    #[inline(always)]
    fn neg_part(self) -> Self {
        Avx512(unsafe { _mm512_min_pd(_mm512_setzero_pd(), self.0) })
    }
    #[inline(always)]
    fn select_nonzero(self, a: Self, b: Self) -> Self {
        Avx512(unsafe {
            let m = _mm512_cmp_pd_mask::<_CMP_NEQ_UQ>(self.0, _mm512_setzero_pd());
            _mm512_mask_blend_pd(m, b.0, a.0)
        })
    }
    #[inline(always)]
    fn min(self, o: Self) -> Self {
        Avx512(unsafe { _mm512_min_pd(self.0, o.0) })
    }
    #[inline(always)]
    fn max(self, o: Self) -> Self {
        Avx512(unsafe { _mm512_max_pd(self.0, o.0) })
    }
}

#[cfg(target_arch = "x86_64")]
impl<const L: usize> Lanes<L> for Avx512 {
    #[inline(always)]
    fn load(p: &[f64; L]) -> Self {
        assert!(L == 8, "Avx512 holds 8 lanes");
        // SAFETY: reads the 8 f64 of `p`; AVX-512F detected.
        Avx512(unsafe { _mm512_loadu_pd(p.as_ptr()) })
    }
    #[inline(always)]
    fn store(self, p: &mut [f64; L]) {
        assert!(L == 8, "Avx512 holds 8 lanes");
        // SAFETY: writes the 8 f64 of `p`; AVX-512F detected.
        unsafe { _mm512_storeu_pd(p.as_mut_ptr(), self.0) }
    }
}
