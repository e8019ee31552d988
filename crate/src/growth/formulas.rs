//! The paper's formulas as pure functions, and the thirds of a plant's height they speak of.
//! `rand` is one value of Rand(), uniform in [0, 1).

use crate::maths;
use crate::vocabulary::Season;
use glam::DVec3;
use serde::Serialize;

/// The paper's three categories of branches by height (Fig 2a). Arrays indexed by a third are in
/// the paper's order: upper, middle, lower.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
pub enum Third {
    Upper = 0,
    Middle = 1,
    Lower = 2,
}

impl Third {
    /// The third of a point at `height` on a plant that spans `low..=high`: the lower third below
    /// one third of the span, the upper third from two thirds up. A plant with no height (every
    /// point at one level) is all middle.
    pub fn of(height: f64, low: f64, high: f64) -> Third {
        let span = high - low;
        let flat = span.is_nan() || span <= 1e-12 * high.abs().max(low.abs()).max(1.0);
        if flat || !height.is_finite() {
            return Third::Middle;
        }
        let t = (height - low) / span;
        if t >= 2.0 / 3.0 {
            Third::Upper
        } else if t >= 1.0 / 3.0 {
            Third::Middle
        } else {
            Third::Lower
        }
    }
}

/// How high the turtle stands at each module of a string, and the plant's extent in height.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Heights {
    /// For each module: the turtle's Y there (the middle of the move for `F f G g`).
    pub modules: Vec<f64>,
    /// The lowest and highest Y the turtle reaches (its start included).
    pub low: f64,
    pub high: f64,
}

impl Heights {
    /// The third of every module.
    pub fn thirds(&self) -> Vec<Third> {
        self.modules
            .iter()
            .map(|&y| Third::of(y, self.low, self.high))
            .collect()
    }
}

/// Round() of the paper: to the nearest whole number, halves away from zero (Rust's `round`).
pub fn paper_round(x: f64) -> f64 {
    x.round()
}

/// Equation (2), the lifetime: NB_i = MB_i + Round(Rand() × VB_i), the number of branches that keep
/// growing at step i. A fractional MB is rounded; the result is never below 0.
pub fn surviving_branches(mean: f64, variance: f64, rand: f64) -> u32 {
    paper_round(mean + paper_round(rand * variance)).clamp(0.0, u32::MAX as f64) as u32
}

/// Shares `survivors` among the upper, middle and lower thirds, which hold `counts` growing
/// apices: in proportion to `probabilities` (largest remainders, ties to the higher third), never
/// more than a third holds; what a third cannot take goes to the others, the most probable first.
/// The result adds up to `min(survivors, counts.sum())`. Table 1: 50 survivors, probabilities
/// 0.6 / 0.3 / 0.1 and counts 32 / 24 / 8 give 30 / 15 / 5.
pub fn share_survivors(survivors: u32, probabilities: [f64; 3], counts: [u32; 3]) -> [u32; 3] {
    let n = survivors.min(counts.iter().sum());
    let sum: f64 = probabilities.iter().filter(|p| **p > 0.0).sum();
    let p = if sum > 0.0 {
        probabilities.map(|x| x.max(0.0) / sum)
    } else {
        [1.0 / 3.0; 3]
    };
    let ideal = p.map(|x| x * n as f64);
    let mut share = ideal.map(|x| x.floor() as u32);
    let mut left = n.saturating_sub(share.iter().sum());
    let mut by_remainder = [0usize, 1, 2];
    crate::sort::sort_by(&mut by_remainder, |&a, &b| {
        let (ra, rb) = (ideal[a] - ideal[a].floor(), ideal[b] - ideal[b].floor());
        rb.total_cmp(&ra).then(a.cmp(&b))
    });
    for k in by_remainder {
        if left == 0 {
            break;
        }
        share[k] += 1;
        left -= 1;
    }
    let mut excess = 0;
    for k in 0..3 {
        if share[k] > counts[k] {
            excess += share[k] - counts[k];
            share[k] = counts[k];
        }
    }
    let mut by_probability = [0usize, 1, 2];
    crate::sort::sort_by(&mut by_probability, |&a, &b| {
        p[b].total_cmp(&p[a]).then(a.cmp(&b))
    });
    for k in by_probability {
        let give = (counts[k] - share[k]).min(excess);
        share[k] += give;
        excess -= give;
    }
    share
}

/// The most rewritings one apex gets in one step (a guard against runaway `#speed` values).
pub const MAX_REWRITINGS: u32 = 100;

/// Equation (3), the speed: NR_i = PF + SM_i + Round(Rand() × VR_i), how many times a branch's
/// apex is rewritten in step i. Rounded, and kept within 0 ..= [`MAX_REWRITINGS`].
pub fn rewritings(positional: f64, seasonal_mean: f64, variance: f64, rand: f64) -> u32 {
    paper_round(positional + seasonal_mean + paper_round(rand * variance))
        .clamp(0.0, MAX_REWRITINGS as f64) as u32
}

/// Equation (4) without its random term, the length of a branch that has lived `age` steps:
/// GR^i up to maturity m, then log_GR(i) − log_GR(m) + GR^m (exponential, then logarithmic
/// growth). Fig 4 (GR 1.5, m 3): 2.25 at age 2, 3.375 at age 3, 4.08 at age 4.
pub fn branch_length(rate: f64, maturity: u32, age: u32) -> f64 {
    if age <= maturity {
        rate.powi(age as i32)
    } else {
        let log = |x: f64| maths::ln(x) / maths::ln(rate);
        log(age as f64) - log(maturity as f64) + rate.powi(maturity as i32)
    }
}

/// Equation (5) without its random term, the width of a branch that has lived `age` steps:
/// BW_i = i + PF.
pub fn branch_width(age: u32, positional: f64) -> f64 {
    age as f64 + positional
}

/// The random term of equations (4) and (5): Round(Rand() × VR).
pub fn variation(rand: f64, variance: f64) -> f64 {
    paper_round(rand * variance)
}

/// The Earth's tilt, the sun's declination at the solstices.
pub const TILT: f64 = 23.5;

/// The sun's altitude at noon, in degrees (section 2.4): 90 − latitude + 23.5 in summer,
/// 90 − latitude at the equinoxes, 90 − latitude − 23.5 in winter. The seasons are the
/// hemisphere's own (a negative latitude is south). At latitude 38: 75.5, 52 and 28.5.
pub fn solar_altitude(latitude: f64, season: Season) -> f64 {
    let tilt = match season {
        Season::Summer => TILT,
        Season::Equinox => 0.0,
        Season::Winter => -TILT,
    };
    90.0 - latitude.abs() + tilt
}

/// The unit vector towards the noon sun: at [`solar_altitude`] above the horizon, towards the
/// equator, which Meristem puts at +X for a northern latitude (the sun stands to the south, on
/// the right of the studio's first view) and at −X for a southern one. An altitude above 90°
/// (the tropics in summer) puts the sun past the zenith. `None` when the sun stays below the
/// horizon (polar winter).
pub fn sun_direction(latitude: f64, season: Season) -> Option<DVec3> {
    let altitude = solar_altitude(latitude, season);
    if altitude <= 0.0 {
        return None;
    }
    let towards_equator = if latitude < 0.0 { -1.0 } else { 1.0 };
    let a = altitude.to_radians();
    Some(DVec3::new(
        towards_equator * maths::cos(a),
        maths::sin(a),
        0.0,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The shares of the thirds in the paper's Table 1 (the defaults of `#lifetime`).
    const TABLE_1: [f64; 3] = [0.6, 0.3, 0.1];

    #[test]
    fn table_1_fifty_of_sixty_four_branches_survive_split_30_15_5() {
        // MB 34, VB 32, Rand() 0.5: NB = 34 + Round(16) = 50.
        let survivors = surviving_branches(34.0, 32.0, 0.5);
        assert_eq!(survivors, 50);
        // The normal 2nd generation's 64 branches: 32 upper, 24 middle, 8 lower.
        let counts = [32, 24, 8];
        let share = share_survivors(survivors, TABLE_1, counts);
        assert_eq!(share, [30, 15, 5]);
        let expired = [0, 1, 2].map(|k| counts[k] - share[k]);
        assert_eq!(expired, [2, 9, 3]);
        assert_eq!(counts.iter().sum::<u32>() - survivors, 14);
    }

    #[test]
    fn nb_follows_rand_between_mb_and_mb_plus_vb() {
        // (MB, VB, rand) and the NB it gives.
        for ((mean, variance, rand), nb) in [
            ((34.0, 32.0, 0.0), 34),
            ((34.0, 32.0, 0.999), 66),
            // Round(0.4 × 5) = 2, Round(0.5 × 5) = Round(2.5) = 3 (halves away from zero).
            ((10.0, 5.0, 0.4), 12),
            ((10.0, 5.0, 0.5), 13),
            ((-3.0, 1.0, 0.2), 0),
        ] {
            assert_eq!(
                surviving_branches(mean, variance, rand),
                nb,
                "{mean} {variance} {rand}"
            );
        }
    }

    #[test]
    fn a_third_that_is_too_small_passes_its_share_on() {
        // 10 survivors by 0.6 / 0.3 / 0.1 would be 6 / 3 / 1, but the upper third has 2 apices:
        // the 4 left over go to the middle third (the next most probable), then the lower.
        assert_eq!(share_survivors(10, TABLE_1, [2, 5, 9]), [2, 5, 3]);
        // More survivors than apices: every apex survives.
        assert_eq!(share_survivors(99, TABLE_1, [3, 2, 1]), [3, 2, 1]);
        // Largest remainders: 7 × (0.6, 0.3, 0.1) = 4.2, 2.1, 0.7 -> 4, 2, 1.
        assert_eq!(share_survivors(7, TABLE_1, [10, 10, 10]), [4, 2, 1]);
        // Unnormalised probabilities are proportions.
        assert_eq!(share_survivors(6, [1.0, 1.0, 1.0], [9, 9, 9]), [2, 2, 2]);
    }

    #[test]
    fn table_2_speed_of_upper_and_other_branches() {
        // (PF, SM, VR, rand) and the NR it gives.
        for ((positional, seasonal_mean, variance, rand), nr) in [
            // SM 0, PF 2 (upper) or 1 (others), VR 1: NR is PF or PF + 1 (Fig 3a).
            ((2.0, 0.0, 1.0, 0.2), 2),
            ((2.0, 0.0, 1.0, 0.7), 3),
            ((1.0, 0.0, 1.0, 0.2), 1),
            ((1.0, 0.0, 1.0, 0.7), 2),
            // VR 2 (Fig 3b): up to PF + 2.
            ((2.0, 0.0, 2.0, 0.9), 4),
            ((1.0, -5.0, 0.0, 0.5), 0),
            ((1.0, 1e9, 0.0, 0.5), MAX_REWRITINGS),
        ] {
            assert_eq!(
                rewritings(positional, seasonal_mean, variance, rand),
                nr,
                "{positional} {seasonal_mean} {variance} {rand}"
            );
        }
    }

    #[test]
    fn fig_4_lengths_grow_exponentially_then_logarithmically() {
        assert_eq!(branch_length(1.5, 3, 0), 1.0);
        assert_eq!(branch_length(1.5, 3, 1), 1.5);
        assert_eq!(branch_length(1.5, 3, 2), 2.25);
        assert_eq!(branch_length(1.5, 3, 3), 3.375);
        // After maturity at step 3: log_1.5(4) − log_1.5(3) + 1.5^3 = 4.0845…; the paper prints
        // 4.078 and the issue "about 4.08".
        let fourth = branch_length(1.5, 3, 4);
        assert!((fourth - 4.084_511).abs() < 1e-6, "{fourth}");
        assert_eq!((fourth * 100.0).round() / 100.0, 4.08);
        // The marginal growth slows down after maturity.
        let gains: Vec<f64> = (1..8)
            .map(|i| branch_length(1.5, 3, i + 1) - branch_length(1.5, 3, i))
            .collect();
        assert!(gains[2] < gains[1], "{gains:?}");
        assert!(gains.windows(2).skip(2).all(|w| w[1] < w[0]), "{gains:?}");
    }

    #[test]
    fn fig_5_widths_grow_with_age_and_position() {
        // PF 2 upper, 1 middle, 0 lower; the width adds one per generation lived.
        let [pu, pm, pl] = [2.0, 1.0, 0.0];
        assert_eq!([1, 2, 3].map(|i| branch_width(i, pu)), [3.0, 4.0, 5.0]);
        assert_eq!(branch_width(1, pm), 2.0);
        assert_eq!(branch_width(1, pl), 1.0);
        assert_eq!(variation(0.7, 2.0), 1.0);
        assert_eq!(variation(0.8, 2.0), 2.0);
    }

    #[test]
    fn solar_altitudes_at_latitude_38() {
        assert_eq!(solar_altitude(38.0, Season::Summer), 75.5);
        assert_eq!(solar_altitude(38.0, Season::Equinox), 52.0);
        assert_eq!(solar_altitude(38.0, Season::Winter), 28.5);
        // The paper rounds to 76 and 29 (and prints 53 for the equinox, where its own formula
        // 90 − latitude gives 52).
        assert_eq!(paper_round(solar_altitude(38.0, Season::Summer)), 76.0);
        assert_eq!(paper_round(solar_altitude(38.0, Season::Winter)), 29.0);
        // The southern hemisphere mirrors the northern one.
        assert_eq!(solar_altitude(-38.0, Season::Summer), 75.5);
    }

    #[test]
    fn the_sun_stands_towards_the_equator_at_its_altitude() {
        let s = sun_direction(38.0, Season::Equinox).expect("up");
        assert!((s.y - maths::sin(52f64.to_radians())).abs() < 1e-12);
        assert!(s.x > 0.0 && s.z == 0.0);
        assert!(sun_direction(-38.0, Season::Equinox).expect("up").x < 0.0);
        // At the Tropic of Cancer in summer the sun is at the zenith; north of the zenith in the
        // tropics.
        let tropic = sun_direction(23.5, Season::Summer).expect("up");
        assert!((tropic - DVec3::Y).length() < 1e-12);
        assert!(sun_direction(10.0, Season::Summer).expect("up").x < 0.0);
        assert_eq!(sun_direction(80.0, Season::Winter), None);
        assert_eq!(Season::named("Spring"), Some(Season::Equinox));
        assert_eq!(Season::named("monsoon"), None);
    }

    #[test]
    fn thirds_divide_the_height() {
        assert_eq!(Third::of(0.0, 0.0, 3.0), Third::Lower);
        assert_eq!(Third::of(0.99, 0.0, 3.0), Third::Lower);
        assert_eq!(Third::of(1.0, 0.0, 3.0), Third::Middle);
        assert_eq!(Third::of(2.0, 0.0, 3.0), Third::Upper);
        assert_eq!(Third::of(3.0, 0.0, 3.0), Third::Upper);
        assert_eq!(Third::of(5.0, 5.0, 5.0), Third::Middle);
    }
}
