//! Modes cached on disk: a second solve of the same pencil for the same
//! request reads the modes back instead of running Lanczos.
//!
//! Key: a 128-bit hash (FNV-1a, 128-bit variant) of the solver version
//! ([`SOLVER_VERSION`]), the bridge kind, the mode count and the content of
//! both matrices (order, sparsity pattern and the bits of every value), so
//! file names, paths and modification times play no part and any change of
//! an entry misses. The file `<key>.modes` in the cache folder holds:
//! magic, key, order, count, the check figures, the eigenvalues and the
//! vectors (column-major), every f64 as its little-endian bits (a cached
//! run equals an uncached one bit for bit), then the 128-bit hash of all
//! that as a checksum.
//!
//! Trust: the checksum is public (anyone can recompute it), so it only
//! catches accidents. A file is used only if its length is exactly the one
//! the request implies (checked before anything is read or allocated), its
//! magic, key, order and count match, and its checksum is right; then the
//! modes are checked again from the model like fresh ones: residuals and
//! M-orthonormality recomputed, and a Sturm count made afresh (one LDLᵀ of
//! K − σM) that must find exactly the stored modes below the cut
//! ([`Pencil::recheck`]), which costs about a tenth of the solve. Anything
//! else (truncated, corrupt, foreign, forged) is not used: the modes are
//! recomputed and written anew, and the outcome says why
//! ([`CacheOutcome::Rejected`]).
//! Writes go through [`crate::atomic_file::write_atomic`] (a temporary
//! file renamed onto the target), so concurrent runs each write a whole
//! file and a reader never sees a partial one.

use std::path::{Path, PathBuf};

use faer::Mat;

use super::sparse::SymmetricSparse;
use super::{Eigenpairs, ModeCheck, Pencil};
use crate::bridge::BridgeError;

/// Changes whenever the solver's results could change (part of the key).
pub const SOLVER_VERSION: &str = "vbi-eigen-lanczos-2";

const MAGIC: &[u8; 8] = b"VBIMODE1";

/// Header: magic, key (16), order, count, 5 check figures, has-inertia flag,
/// inertia count, dense flag (each 8 bytes).
const HEADER_BYTES: usize = 8 + 16 + 8 * 10;

/// A 128-bit FNV-1a hash (Fowler–Noll–Vo, 128-bit parameters).
#[derive(Debug, Clone)]
pub struct Hasher(u128);

impl Default for Hasher {
    fn default() -> Self {
        Self(0x6c62_272e_07bb_0142_62b8_2175_6295_c58d)
    }
}

impl Hasher {
    /// Feeds bytes.
    pub fn bytes(&mut self, bytes: &[u8]) {
        const PRIME: u128 = 0x0000_0000_0100_0000_0000_0000_0000_013b;
        for &b in bytes {
            self.0 ^= u128::from(b);
            self.0 = self.0.wrapping_mul(PRIME);
        }
    }

    /// Feeds a number as its 8 little-endian bytes.
    pub fn number(&mut self, x: u64) {
        self.bytes(&x.to_le_bytes());
    }

    /// Feeds a sparse matrix: order, pattern and value bits.
    pub fn matrix(&mut self, a: &SymmetricSparse) {
        self.number(a.nrows() as u64);
        self.number(a.ncols() as u64);
        for &p in a.symbolic().col_ptr() {
            self.number(p as u64);
        }
        for &i in a.symbolic().row_idx() {
            self.number(i as u64);
        }
        for &v in a.val() {
            self.number(v.to_bits());
        }
    }

    /// The hash.
    pub fn finish(&self) -> u128 {
        self.0
    }
}

/// A folder of cached modes and the kind of bridge they belong to.
#[derive(Debug, Clone)]
pub struct ModesCache {
    /// The folder (created on first write).
    pub folder: PathBuf,
    /// The bridge kind (`beam`, `plate`, `fe_import`, …), part of the key.
    pub kind: String,
}

/// Whether the modes came from the cache.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum CacheOutcome {
    /// Read from a valid cache file (and re-checked).
    Hit,
    /// Solved (no file), then written.
    Miss,
    /// A file was there but failed a check (the reason): solved afresh and
    /// written anew.
    Rejected(&'static str),
}

/// What [`ModesCache::read`] found.
#[derive(Debug)]
pub enum Read {
    /// No file for the key.
    Absent,
    /// A file that is not a cache file of this request (the reason).
    Invalid(&'static str),
    /// A well-formed file, not yet re-checked.
    Valid(Eigenpairs),
}

impl ModesCache {
    /// The key of `count` modes of `pencil`.
    pub fn key(&self, pencil: &Pencil, count: usize) -> u128 {
        let mut h = Hasher::default();
        h.bytes(SOLVER_VERSION.as_bytes());
        h.number(self.kind.len() as u64);
        h.bytes(self.kind.as_bytes());
        h.number(count as u64);
        h.matrix(&pencil.stiffness);
        h.matrix(&pencil.mass);
        h.finish()
    }

    /// The file of a key.
    pub fn path(&self, key: u128) -> PathBuf {
        self.folder.join(format!("{key:032x}.modes"))
    }

    /// Reads the modes of `key` if a valid file holds them (module doc).
    /// Sizes come from the request (`order`, `count`), never from the file:
    /// its length must equal the one they imply before anything is read or
    /// allocated, so a file claiming 10¹² modes costs nothing.
    pub fn read(&self, key: u128, order: usize, count: usize) -> Read {
        let path = self.path(key);
        let Ok(metadata) = std::fs::metadata(&path) else {
            return Read::Absent;
        };
        let Some(expected) = file_len(order, count) else {
            return Read::Invalid("the request's size overflows");
        };
        if metadata.len() != expected as u64 {
            return Read::Invalid("its length is not that of the request");
        }
        // A regular file of exactly that length, read no further.
        let Ok(bytes) = crate::guarded_file::read_bounded(&path, expected as u64) else {
            return Read::Invalid("it cannot be read");
        };
        match decode(&bytes, key, order, count) {
            Some(pairs) => Read::Valid(pairs),
            None => Read::Invalid("its header or checksum is wrong"),
        }
    }

    /// Writes `pairs` under `key` (atomically). Errors are the caller's to
    /// report or ignore (a cache that cannot be written only costs time).
    pub fn write(&self, key: u128, pairs: &Eigenpairs) -> std::io::Result<()> {
        std::fs::create_dir_all(&self.folder)?;
        crate::atomic_file::write_atomic(&self.path(key), &encode(key, pairs))
    }
}

/// Bytes of a file of `count` modes of order `order` (None on overflow).
fn file_len(order: usize, count: usize) -> Option<usize> {
    let values = count.checked_mul(order)?.checked_add(count)?;
    values.checked_mul(8)?.checked_add(HEADER_BYTES + 16)
}

fn encode(key: u128, pairs: &Eigenpairs) -> Vec<u8> {
    let (order, count) = (pairs.vectors.nrows(), pairs.vectors.ncols());
    let mut out = Vec::with_capacity(file_len(order, count).unwrap_or(0));
    out.extend_from_slice(MAGIC);
    out.extend_from_slice(&key.to_le_bytes());
    let c = &pairs.check;
    let (shift, counted) = c.inertia.unwrap_or((f64::NAN, 0));
    for word in [
        order as u64,
        count as u64,
        c.largest_residual.to_bits(),
        c.largest_plain_residual.to_bits(),
        c.orthonormality_error.to_bits(),
        shift.to_bits(),
        u64::from(c.inertia.is_some()),
        counted as u64,
        u64::from(c.dense),
        0,
    ] {
        out.extend_from_slice(&word.to_le_bytes());
    }
    for &lambda in &pairs.eigenvalues {
        out.extend_from_slice(&lambda.to_bits().to_le_bytes());
    }
    for j in 0..count {
        for &v in pairs.vectors.col(j).iter() {
            out.extend_from_slice(&v.to_bits().to_le_bytes());
        }
    }
    let mut h = Hasher::default();
    h.bytes(&out);
    out.extend_from_slice(&h.finish().to_le_bytes());
    out
}

fn decode(bytes: &[u8], key: u128, order: usize, count: usize) -> Option<Eigenpairs> {
    if bytes.len() != file_len(order, count)? {
        return None;
    }
    let (body, checksum) = bytes.split_at(bytes.len() - 16);
    let mut h = Hasher::default();
    h.bytes(body);
    if h.finish().to_le_bytes() != checksum || &body[..8] != MAGIC {
        return None;
    }
    if body[8..24] != key.to_le_bytes() {
        return None;
    }
    let word = |i: usize| {
        let at = 24 + 8 * i;
        u64::from_le_bytes(body[at..at + 8].try_into().expect("8 bytes"))
    };
    if word(0) != order as u64 || word(1) != count as u64 {
        return None;
    }
    let float = |i: usize| f64::from_bits(word(i));
    let check = ModeCheck {
        largest_residual: float(2),
        largest_plain_residual: float(3),
        orthonormality_error: float(4),
        inertia: (word(6) == 1).then(|| (float(5), word(7) as usize)),
        dense: word(8) == 1,
    };
    let data = &body[HEADER_BYTES..];
    let value = |i: usize| {
        f64::from_bits(u64::from_le_bytes(
            data[8 * i..8 * i + 8].try_into().expect("8 bytes"),
        ))
    };
    let eigenvalues = (0..count).map(value).collect();
    let vectors = Mat::from_fn(order, count, |i, j| value(count + j * order + i));
    Some(Eigenpairs {
        eigenvalues,
        vectors,
        check,
    })
}

impl Pencil {
    /// [`Pencil::lowest`] through `cache`: a valid cached file is read and
    /// its modes checked again from the model ([`Pencil::recheck`]);
    /// otherwise the modes are solved and written (a write failure is
    /// returned as `Err` only for the solve's errors: the cache is an
    /// optimisation, its I/O errors are ignored). A file that was there but
    /// failed a check is reported in the outcome ([`CacheOutcome::Rejected`]).
    pub fn lowest_cached(
        &self,
        count: usize,
        cache: &ModesCache,
    ) -> Result<(Eigenpairs, CacheOutcome), BridgeError> {
        let key = cache.key(self, count);
        let rejected = match cache.read(key, self.order(), count) {
            Read::Absent => None,
            Read::Invalid(why) => Some(why),
            Read::Valid(mut pairs) => match self.recheck(&mut pairs) {
                Ok(()) => return Ok((pairs, CacheOutcome::Hit)),
                Err(why) => Some(why),
            },
        };
        let pairs = self.lowest(count)?;
        // A cut that needed more modes than the file holds (a cluster
        // straddling the request) could not be re-counted: not written.
        if pairs
            .check
            .inertia
            .is_none_or(|(_, counted)| counted == count)
        {
            let _ = cache.write(key, &pairs);
        }
        let outcome = match rejected {
            Some(why) => CacheOutcome::Rejected(why),
            None => CacheOutcome::Miss,
        };
        Ok((pairs, outcome))
    }

    /// The checks of fresh modes, made again from the model on cached ones;
    /// nothing the file says about completeness is believed:
    /// - the eigenvalues are finite, positive and ascending;
    /// - residuals and M-orthonormality recomputed ([`Pencil::verify`]);
    /// - completeness by a Sturm count made here (one LDLᵀ of K − σM): at
    ///   the file's shift σ, above every stored eigenvalue by a margin
    ///   checked below, exactly `count` eigenvalues of the model may lie
    ///   (fewer modes than the order; `count` = order needs no count).
    ///
    /// Why the count proves that none is missing: for a vector φ with
    /// energy residual η (module doc of [`super`]), expanding φ = Σ aⱼφⱼ in
    /// the true modes gives η² = Σ aⱼ²λⱼ((λⱼ − λ̃)/λⱼ)² / Σ aⱼ²λⱼ, so the
    /// part of φ on modes at or above σ has M-norm at most η/g with
    /// g = 1 − λ̃/σ. With g ≥ [`CUT_MARGIN`]·η every stored vector lies
    /// within 1 % of the span of the modes below σ; `count` M-orthonormal
    /// such vectors span all of it when exactly `count` modes lie below σ.
    /// A file that drops a mode and adds the next one above (the forgery
    /// of issue 23) has one more eigenvalue below σ than vectors.
    /// The figures must also equal the stored ones (they are computed the
    /// same way), so a cached run reports what a fresh one does.
    fn recheck(&self, pairs: &mut Eigenpairs) -> Result<(), &'static str> {
        let stored = pairs.check;
        let values = &pairs.eigenvalues;
        if values.iter().any(|&l| !(l > 0.0 && l.is_finite()))
            || values.windows(2).any(|w| w[1] < w[0])
        {
            return Err("its eigenvalues are not positive and ascending");
        }
        self.verify(pairs, |x, y| super::sparse::multiply(&self.stiffness, x, y))
            .map_err(|_| "its modes fail the residual or orthonormality check")?;
        let count = pairs.eigenvalues.len();
        let inertia = if count == self.order() {
            None
        } else {
            let Some((shift, _)) = stored.inertia else {
                return Err("it has no Sturm cut below the model's order");
            };
            let last = pairs.eigenvalues[count - 1];
            let margin = CUT_MARGIN * pairs.check.largest_residual;
            if !(shift.is_finite() && 1.0 - last / shift >= margin && shift > last) {
                return Err("its Sturm cut is not clear of its last mode");
            }
            let below = self
                .count_below(shift)
                .map_err(|_| "its Sturm cut cannot be factorised")?;
            if below != count {
                return Err("a Sturm count of the model disagrees (a mode is missing)");
            }
            Some((shift, below))
        };
        pairs.check.inertia = inertia;
        if pairs.check != stored {
            return Err("its check figures differ from the recomputed ones");
        }
        Ok(())
    }
}

/// How far (relative to the largest energy residual η) the Sturm cut of a
/// cached file must lie above its last mode, 1 − λ̃/σ ≥ 100 η, so that each
/// stored vector is within 1 % of the modes below the cut
/// ([`Pencil::recheck`]).
const CUT_MARGIN: f64 = 100.0;

/// The default cache folder inside an output root: `<root>/.vbi-cache`.
pub fn default_folder(output_root: &Path) -> PathBuf {
    output_root.join(".vbi-cache")
}
