//! Lane vectors for the lock-step RK4 kernels, and the instruction set
//! chosen at run time.
//!
//! A kernel is written once, generic over [`Simd`] (a value holding one
//! `f64` per lane); it is instantiated with plain `f64` (one lane) and with
//! lane arrays ([`Portable`]) whose operations are plain loops over the
//! lanes. The compiler turns those loops into vector instructions of the
//! enclosing function's target: SSE2 (x86-64 baseline) or NEON, and inside
//! the `#[target_feature]` entry points of `batch.rs` (entered only after
//! `is_x86_feature_detected!` confirmed the CPU has them) AVX2 or AVX-512.
//! No closures: nothing the compiler might decline to inline into the hot
//! loop. The compiler's AVX-512 code for the arrays is poor, so 8-lane
//! batches on AVX-512 use [`Avx512`] registers through intrinsics instead.
//!
//! Every operation is a single IEEE-754 operation with the same rounding in
//! every instantiation (add, sub, mul, compare/select, min/max against zero):
//! no fused multiply-add, no reassociation. A lane therefore gives bitwise
//! the same result in every instantiation and on every CPU, whatever lanes it
//! is grouped with (tested in `batch.rs`).

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

/// A lane-wise operation as a plain loop (no closure, nothing to inline).
macro_rules! lanewise {
    ($name:ident, |$a:ident, $b:ident| $e:expr) => {
        #[inline(always)]
        fn $name(self, o: Self) -> Self {
            let mut r = self.0;
            for l in 0..L {
                let ($a, $b) = (self.0[l], o.0[l]);
                r[l] = $e;
            }
            Portable(r)
        }
    };
}

impl<const L: usize> Simd for Portable<L> {
    #[inline(always)]
    fn splat(v: f64) -> Self {
        Portable([v; L])
    }
    lanewise!(add, |a, b| a + b);
    lanewise!(sub, |a, b| a - b);
    lanewise!(mul, |a, b| a * b);
    lanewise!(min, |a, b| if a < b { a } else { b });
    lanewise!(max, |a, b| if a > b { a } else { b });
    #[inline(always)]
    fn pos_part(self) -> Self {
        let mut r = self.0;
        for v in &mut r {
            *v = if 0.0 > *v { 0.0 } else { *v };
        }
        Portable(r)
    }
    #[inline(always)]
    fn neg_part(self) -> Self {
        let mut r = self.0;
        for v in &mut r {
            *v = if 0.0 < *v { 0.0 } else { *v };
        }
        Portable(r)
    }
    // Index loops on purpose: iterator adapters are calls the compiler may
    // leave un-inlined in a large kernel.
    #[allow(clippy::needless_range_loop)]
    #[inline(always)]
    fn select_nonzero(self, a: Self, b: Self) -> Self {
        let mut r = b.0;
        for l in 0..L {
            if self.0[l] != 0.0 {
                r[l] = a.0[l];
            }
        }
        Portable(r)
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
    /// x86-64 AVX2: 4 lanes per register (8-lane batches as portable arrays
    /// compiled for AVX2).
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
    /// AVX-512 (one register), 4 otherwise (8 lanes in two AVX2 or four
    /// SSE2 registers run out of registers: slower per lane than 4).
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

#[cfg(target_arch = "x86_64")]
use std::arch::x86_64::*;

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
