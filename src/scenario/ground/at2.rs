//! PEER NGA `.AT2` acceleration files (the PEER Ground Motion Database's
//! format): four header lines — title, event and station, the quantity and
//! its units (`ACCELERATION TIME SERIES IN UNITS OF G`), the sample count
//! and interval (`NPTS=  4000, DT=   .0100 SEC`, or in the older layout
//! `  4000    .01000    NPTS, DT`) — then NPTS accelerations, several per
//! line, at t = 0, DT, 2 DT, …
//!
//! Every problem is an error with the file's own line number; the declared
//! NPTS is checked against the caller's limit before anything is allocated
//! per sample.

use crate::scene::AccelerationUnit;

/// A parsed `.AT2` record: samples at k·`interval`, in `unit`.
#[derive(Debug, Clone, PartialEq)]
pub struct At2 {
    /// Sampling interval DT, s.
    pub interval: f64,
    /// Accelerations, in `unit`.
    pub acceleration: Vec<f64>,
    /// The unit the header states.
    pub unit: AccelerationUnit,
}

/// Why a file could not be read: (1-based line, message).
pub type At2Error = (usize, String);

/// The sample count a header declares, for a budget check before
/// [`parse`] allocates: `Ok(NPTS)`.
#[allow(dead_code)] // Public before the move; only its test calls it now.
pub fn declared_points(text: &str) -> Result<usize, At2Error> {
    let line = text
        .lines()
        .nth(3)
        .ok_or((text.lines().count().max(1), header_missing()))?;
    Ok(npts_dt(line)?.0)
}

fn header_missing() -> String {
    "a PEER .AT2 file starts with four header lines (title; event; `ACCELERATION … IN UNITS OF G`; \
     `NPTS= n, DT= dt SEC`); this one ends before them"
        .to_owned()
}

/// NPTS and DT of header line 4 (either layout).
fn npts_dt(line: &str) -> Result<(usize, f64), At2Error> {
    let upper = line.to_ascii_uppercase();
    let number_after = |key: &str| -> Option<&str> {
        let at = upper.find(key)? + key.len();
        let rest = line[at..].trim_start();
        let end = rest
            .find(|c: char| c == ',' || c.is_whitespace())
            .unwrap_or(rest.len());
        Some(&rest[..end])
    };
    let (npts, dt) = if upper.contains("NPTS=") || upper.contains("NPTS =") {
        let npts = number_after("NPTS=").or_else(|| number_after("NPTS ="));
        let dt = number_after("DT=").or_else(|| number_after("DT ="));
        (npts, dt)
    } else {
        let mut tokens = line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|t| !t.is_empty());
        (tokens.next(), tokens.next())
    };
    let bad = || {
        (
            4,
            "header line 4 must give the sample count and interval, `NPTS= 4000, DT= .0100 SEC` \
             (or `4000  .0100  NPTS, DT`); is it a PEER AT2 file?"
                .to_string(),
        )
    };
    let npts: usize = npts.and_then(|s| s.parse().ok()).ok_or_else(bad)?;
    let dt: f64 = dt.and_then(|s| s.parse().ok()).ok_or_else(bad)?;
    if npts < 2 {
        return Err((
            4,
            format!("NPTS = {npts}: a record needs at least two samples"),
        ));
    }
    if !(dt.is_finite() && dt > 0.0) {
        return Err((
            4,
            format!("DT = {dt}: the sampling interval must be a positive number of seconds"),
        ));
    }
    let (lo, hi) = super::SAMPLING_INTERVAL;
    if !(lo..=hi).contains(&dt) {
        return Err((
            4,
            format!(
                "DT = {dt:e} s is outside the plausible sampling interval of a ground-motion \
                 record, {lo:e} to {hi} s (accelerographs sample at 50–1000 Hz)"
            ),
        ));
    }
    let duration = (npts - 1) as f64 * dt;
    if duration > super::RECORD_DURATION {
        return Err((
            4,
            format!(
                "NPTS = {npts} samples at DT = {dt} s last {duration:e} s, more than the \
                 plausible {} s (one day) of a ground-motion record",
                super::RECORD_DURATION
            ),
        ));
    }
    Ok((npts, dt))
}

/// The unit of header line 3: `… IN UNITS OF G`, `… (G)`, `… CM/S/S`, …
fn unit_of(line: &str) -> Result<AccelerationUnit, At2Error> {
    let upper = line.to_ascii_uppercase();
    if !upper.contains("ACCEL") {
        return Err((
            3,
            "header line 3 must say the file holds accelerations (`ACCELERATION TIME SERIES IN \
             UNITS OF G`); it does not (velocity and displacement files, .VT2 and .DT2, are not \
             ground accelerations)"
                .to_string(),
        ));
    }
    let candidate = if let Some(at) = upper.find("UNITS OF") {
        upper[at + 8..]
            .trim()
            .trim_end_matches(['.', ')'])
            .to_owned()
    } else if let (Some(open), Some(close)) = (upper.find('('), upper.rfind(')')) {
        upper[open + 1..close].to_owned()
    } else {
        upper.split_whitespace().last().unwrap_or("").to_owned()
    };
    let word = candidate.split([' ', ',', ':']).next().unwrap_or("");
    AccelerationUnit::parse(word).ok_or((
        3,
        "header line 3 does not state the units of the accelerations as g, cm/s^2 or m/s^2"
            .to_string(),
    ))
}

/// Parses a whole `.AT2` file. `max_points` bounds the declared NPTS
/// (checked before any allocation).
pub fn parse(text: &str, max_points: usize) -> Result<At2, At2Error> {
    let mut lines = text.lines();
    let (_title, _event) = (lines.next(), lines.next());
    let unit_line = lines
        .next()
        .ok_or((text.lines().count().max(1), header_missing()))?;
    let count_line = lines
        .next()
        .ok_or((text.lines().count().max(1), header_missing()))?;
    let unit = unit_of(unit_line)?;
    let (npts, interval) = npts_dt(count_line)?;
    if npts > max_points {
        return Err((
            4,
            format!(
                "NPTS = {npts} is more than the {max_points} samples that the file's size and `limits.ground_points` allow"
            ),
        ));
    }
    let mut acceleration = Vec::with_capacity(npts);
    for (i, line) in lines.enumerate() {
        let n = i + 5;
        for token in line
            .split(|c: char| c == ',' || c.is_whitespace())
            .filter(|t| !t.is_empty())
        {
            let value: f64 = token.parse().map_err(|_| {
                (
                    n,
                    format!("`{}` is not a number", crate::text_table::quoted(token)),
                )
            })?;
            if !value.is_finite() {
                return Err((
                    n,
                    format!(
                        "`{}` is not a finite number",
                        crate::text_table::quoted(token)
                    ),
                ));
            }
            if acceleration.len() == npts {
                return Err((
                    n,
                    format!("the header declares NPTS = {npts} samples but the file holds more"),
                ));
            }
            acceleration.push(value);
        }
    }
    if acceleration.len() != npts {
        return Err((
            text.lines().count().max(1),
            format!(
                "the header declares NPTS = {npts} samples but the file holds {} (truncated?)",
                acceleration.len()
            ),
        ));
    }
    Ok(At2 {
        interval,
        acceleration,
        unit,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const WEST2: &str = "PEER NGA STRONG MOTION DATABASE RECORD\n\
        Imperial Valley-02, 5/19/1940, El Centro Array #9, 180\n\
        ACCELERATION TIME SERIES IN UNITS OF G\n\
        NPTS=     5, DT=   .0100 SEC\n\
        \x20 .63066E-02  .36366E-02  .99227E-03\n\
        \x20-.10089E-02 -.12000E-02\n";

    #[test]
    fn reads_both_header_layouts() {
        let r = parse(WEST2, 100).unwrap();
        assert_eq!(r.interval, 0.01);
        assert_eq!(r.unit, AccelerationUnit::StandardGravity);
        assert_eq!(
            r.acceleration,
            vec![0.0063066, 0.0036366, 0.00099227, -0.0010089, -0.0012]
        );
        let old = "PEER NGA STRONG MOTION DATABASE RECORD\nX\n\
                   ACCELERATION TIME HISTORY IN UNITS OF G\n  3    0.00500    NPTS, DT\n1 2 3\n";
        let r = parse(old, 100).unwrap();
        assert_eq!((r.interval, r.acceleration.len()), (0.005, 3));
        assert_eq!(declared_points(WEST2), Ok(5));
    }

    #[test]
    fn bad_files_are_located() {
        assert_eq!(
            parse(&WEST2.replace("NPTS=     5", "NPTS=     6"), 100)
                .unwrap_err()
                .0,
            6
        );
        assert_eq!(
            parse(&WEST2.replace("NPTS=     5", "NPTS=     4"), 100)
                .unwrap_err()
                .0,
            6
        );
        assert_eq!(
            parse(&WEST2.replace("-.12000E-02", "nan"), 100)
                .unwrap_err()
                .0,
            6
        );
        assert_eq!(
            parse(&WEST2.replace("-.12000E-02", "x"), 100)
                .unwrap_err()
                .0,
            6
        );
        assert_eq!(
            parse(&WEST2.replace("UNITS OF G", "UNITS OF FT"), 100)
                .unwrap_err()
                .0,
            3
        );
        assert_eq!(
            parse(&WEST2.replace("ACCELERATION", "VELOCITY"), 100)
                .unwrap_err()
                .0,
            3
        );
        assert_eq!(parse(&WEST2.replace(".0100", "-1"), 100).unwrap_err().0, 4);
        // More samples than the budget allows, within a plausible duration:
        // the budget refuses it (before anything is allocated).
        let many = WEST2.replace("NPTS=     5", "NPTS=  1000");
        assert!(
            parse(&many, 100)
                .unwrap_err()
                .1
                .contains("limits.ground_points")
        );
        // 10^12 samples at 0.01 s would last 317 years: refused at line 4
        // before the budget is even asked.
        let huge = WEST2.replace("NPTS=     5", "NPTS= 1000000000000");
        assert!(parse(&huge, 100).unwrap_err().1.contains("one day"));
        assert_eq!(parse("PEER\nX\n", 100).unwrap_err().0, 2);
    }
}
