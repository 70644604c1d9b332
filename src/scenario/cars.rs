//! A train's cars, shared by `train` and `train_3d`: `count` identical cars
//! at `car_spacing`, or a `cars` list of spacings and per-car overrides.
//! Each car's offset (its front wheelset behind the train's first, m) is
//! the running sum of the spacings, summed in the same order whichever form
//! was given, so the resolved scene (written as a `cars` list) resolves to
//! the same offsets bit for bit.

use super::checker::Checker;
use super::rail::MAX_CARS;

/// How one kind of car is resolved and checked.
pub(crate) struct CarRules<P, R> {
    /// Applies the overrides `raw` (blamed at `path`) to the parameters.
    pub apply: fn(&mut P, Option<&R>, &str, &mut Checker<'_>),
    /// Checks one car's parameters as a whole (blamed at `path`), after
    /// its overrides.
    pub check: fn(&mut Checker<'_>, &str, &P),
    /// The car's wheelset span 2(a + b), m: a spacing must exceed the car
    /// ahead's.
    pub span: fn(&P) -> f64,
}

/// One resolved car.
pub(crate) struct Car<P> {
    /// Distance from the car ahead's front wheelset, m; none for the first.
    pub spacing: Option<f64>,
    /// Distance of the front wheelset behind the train's first, m.
    pub offset: f64,
    /// The car's parameters.
    pub parameters: P,
}

/// The cars of the train at `at`: `shared` holds the train's parameters
/// (its own overrides applied, blamed at `shared_at`), `list` the `cars`
/// list as (spacing, overrides). Without `count` or a list the train is
/// one car if `one_by_default`, else an error.
#[allow(clippy::too_many_arguments)]
pub(crate) fn resolve_cars<P: Copy, R>(
    ck: &mut Checker<'_>,
    at: &str,
    rules: &CarRules<P, R>,
    shared: P,
    shared_at: &str,
    count: Option<usize>,
    car_spacing: Option<f64>,
    list: Option<Vec<(Option<f64>, Option<&R>)>>,
    one_by_default: bool,
) -> Vec<Car<P>> {
    let mut cars = Vec::new();
    match (count, car_spacing, list) {
        (Some(_), _, Some(_)) => ck.error(
            &format!("{at}.cars"),
            "give `count` (with `car_spacing`) or `cars`, not both",
        ),
        (None, Some(_), Some(_)) => ck.error(
            &format!("{at}.car_spacing"),
            "`car_spacing` goes with `count`; in a `cars` list each car gives its `spacing`",
        ),
        (None, _, None) if !one_by_default => ck.error(
            at,
            "a train needs `count` (with `car_spacing`) or a `cars` list",
        ),
        (count, spacing, None) => {
            let n = count.unwrap_or(1);
            if n == 0 || n > MAX_CARS {
                ck.error(
                    &format!("{at}.count"),
                    format!("a train has 1 to {MAX_CARS} cars, got {n}"),
                );
            } else if n > 1 && spacing.is_none() {
                ck.error(at, "`count` cars need `car_spacing`, m");
            } else {
                (rules.check)(ck, shared_at, &shared);
                let spacing = spacing.unwrap_or(0.0);
                if n > 1 {
                    check_spacing(
                        ck,
                        &format!("{at}.car_spacing"),
                        spacing,
                        (rules.span)(&shared),
                    );
                }
                let mut offset = 0.0;
                for k in 0..n {
                    let spacing = (k > 0).then_some(spacing);
                    offset += spacing.unwrap_or(0.0);
                    cars.push(Car {
                        spacing,
                        offset,
                        parameters: shared,
                    });
                }
            }
        }
        (None, None, Some(list)) => {
            if list.is_empty() {
                ck.error(&format!("{at}.cars"), "`cars` needs at least one car");
            }
            let mut offset = 0.0;
            let mut previous: Option<P> = None;
            for (k, (spacing, overrides)) in list.into_iter().enumerate() {
                let path = format!("{at}.cars[{k}]");
                let mut parameters = shared;
                let car_at = format!("{path}.parameters");
                (rules.apply)(&mut parameters, overrides, &car_at, ck);
                (rules.check)(ck, &car_at, &parameters);
                match (previous, spacing) {
                    (None, Some(_)) => ck.error(
                        &format!("{path}.spacing"),
                        "the first car has no car ahead: leave out its `spacing`",
                    ),
                    (Some(_), None) => ck.error(
                        &path,
                        "every car but the first needs `spacing`, m from the front wheelset \
                         of the car ahead",
                    ),
                    (Some(ahead), Some(s)) => {
                        check_spacing(ck, &format!("{path}.spacing"), s, (rules.span)(&ahead));
                        offset += s;
                    }
                    (None, None) => {}
                }
                cars.push(Car {
                    spacing: spacing.filter(|_| k > 0),
                    offset,
                    parameters,
                });
                previous = Some(parameters);
            }
        }
    }
    cars
}

/// A car spacing must leave the car ahead's wheelsets in front of this
/// car's: spacing > 2(a + b) of the car ahead (`span`, m).
fn check_spacing(ck: &mut Checker<'_>, path: &str, spacing: f64, span: f64) {
    ck.positive(path, spacing, "car spacing");
    if spacing > 0.0 && spacing <= span {
        ck.error(
            path,
            format!(
                "a car spacing of {spacing} m overlaps the car ahead, whose wheelsets span \
                 {span} m (2 × (half_bogie_spacing + half_wheelbase)); cars are spaced front \
                 wheelset to front wheelset"
            ),
        );
    }
}
