//! The model's verdict "which approach does my system need?" (`system::compliant::verdict`) in
//! words with its numbers, for the command line and the explorer alike.

use crate::model::system::compliant::verdict::{
    LONG_CONTACT, NothingRecorded, Quantity, Resting, Validity, Verdict,
};

use super::{Zeros, significant};

/// Realised and asked e closer than this are not worth a clause.
const RESTITUTION_SHOWN: f64 = 0.005;

/// The quantity's name in a sentence.
pub fn quantity_name(quantity: Quantity) -> &'static str {
    match quantity {
        Quantity::MeanImpactSpeed => "mean impact speed",
        Quantity::MeanImpactPhase => "mean impact phase",
        Quantity::ImpactRate => "impacts per period",
    }
}

/// A fraction as a percentage with two significant digits: 0.0123 → `1.2 %`.
fn percent(fraction: f64) -> String {
    format!("{} %", significant(100.0 * fraction, 2, Zeros::Trim))
}

/// How a comparison's difference reads: a relative difference, or for the phase a fraction of
/// the period.
fn difference(quantity: Quantity, relative: f64) -> String {
    match quantity {
        Quantity::MeanImpactPhase => format!("{} of a period", percent(relative.abs())),
        _ => percent(relative.abs()),
    }
}

/// The gist, for narrow panes.
pub fn gist(verdict: &Verdict) -> &'static str {
    match verdict.validity {
        Validity::Valid => "rigid stop is enough",
        Validity::Marginal => "rigid stop: check",
        Validity::NotValid => "needs the compliant stop",
    }
}

/// The verdict in one sentence with its numbers.
pub fn sentence(verdict: &Verdict) -> String {
    let law = verdict.law.label();
    let contacts = format!(
        "contacts last {} of a forcing period",
        percent(verdict.contact_ratio)
    );
    let mut text = match verdict.comparisons.get(verdict.decisive) {
        _ if verdict.impacts.1 == 0 => nothing_recorded(verdict.nothing_recorded),
        None => format!("no impacts to compare; {contacts}"),
        Some(c) => {
            let by = difference(c.quantity, c.relative());
            let what = quantity_name(c.quantity);
            match verdict.validity {
                Validity::Valid => format!(
                    "the instantaneous model is within {by} of the {law} stop on the {what} \
                     here; {contacts}"
                ),
                Validity::Marginal => format!(
                    "the instantaneous model is an approximation here: {contacts}, and the \
                     {what} differs by {by} from the {law} stop's"
                ),
                Validity::NotValid if verdict.contact_ratio > LONG_CONTACT => {
                    format!("not valid: the stop is soft, {contacts} (the {what} differs by {by})")
                }
                Validity::NotValid => format!(
                    "not valid: the {what} differs by {by} from the {law} stop's, though {contacts}"
                ),
            }
        }
    };
    if let Some(clause) = resting(verdict) {
        text.push_str(&clause);
    }
    if (verdict.realised_restitution - verdict.asked_restitution).abs() > RESTITUTION_SHOWN
        && let Some(c) = verdict.comparisons.get(verdict.decisive)
    {
        text.push_str(&format!(
            "; the law realises e = {}, not the {} asked: against a rigid stop at e = {} the \
             {} differs by {}",
            significant(verdict.realised_restitution, 3, Zeros::Trim),
            significant(verdict.asked_restitution, 3, Zeros::Trim),
            significant(verdict.realised_restitution, 3, Zeros::Trim),
            quantity_name(c.quantity),
            difference(c.quantity, c.relative_at_realised()),
        ));
    }
    text
}

/// Why there is nothing to compare: the compliant run recorded no impact proper.
fn nothing_recorded(why: Option<NothingRecorded>) -> String {
    match why {
        Some(NothingRecorded::TransientUnfinished {
            impacts,
            transient,
            periods,
        }) => {
            format!(
                "no impacts to compare: the compliant run's transient never ended: it reached \
                 --max-periods ({} forcing periods) after {impacts} of its {transient} transient \
                 impacts, one every {} forcing periods on average: the motion does not \
                 settle within the run",
                significant(periods, 3, Zeros::Trim),
                significant(periods / impacts.max(1) as f64, 3, Zeros::Trim),
            )
        }
        Some(NothingRecorded::RestsForever) => {
            "no impacts to compare: the compliant stop's body comes to rest on it for ever".into()
        }
        Some(NothingRecorded::NoBounce) | None => {
            "no impacts to compare: the compliant stop's body does not bounce here".into()
        }
    }
}

/// The resting phases, separate from the contacts: `; the body also rests on the stop 30 % of
/// the time (4 resting phases, not counted as contacts; with the rigid stop 28 %)`.
fn resting(verdict: &Verdict) -> Option<String> {
    let (c, r) = (verdict.compliant_resting, verdict.rigid_resting);
    if c.phases == 0 && r.phases == 0 {
        return None;
    }
    let phases = |p: Resting| {
        format!(
            "{} resting phase{}",
            p.phases,
            if p.phases == 1 { "" } else { "s" }
        )
    };
    Some(format!(
        "; the body also rests on the stop {} of the time ({}, not counted as contacts; with \
         the rigid stop {}, {})",
        percent(c.fraction),
        phases(c),
        percent(r.fraction),
        phases(r),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::model::ForceModel;
    use crate::model::system::compliant::verdict::Comparison;

    fn verdict(ratio: f64, rigid: f64, realised: f64, validity: Validity) -> Verdict {
        Verdict {
            law: ForceModel::HuntCrossley,
            period: 0.01,
            contact_time: ratio * 0.01,
            contact_ratio: ratio,
            asked_restitution: 0.5,
            realised_restitution: realised,
            comparisons: vec![Comparison {
                quantity: Quantity::MeanImpactSpeed,
                rigid,
                rigid_at_realised: 1.0,
                compliant: 1.0,
            }],
            decisive: 0,
            validity,
            impacts: (10, 10),
            rigid_resting: Resting::default(),
            compliant_resting: Resting::default(),
            nothing_recorded: None,
        }
    }

    #[test]
    fn each_verdict_reads_with_its_numbers() {
        assert_eq!(
            sentence(&verdict(0.0082, 1.003, 0.5, Validity::Valid)),
            "the instantaneous model is within 0.3 % of the Hunt–Crossley (eq 19) stop on the \
             mean impact speed here; contacts last 0.82 % of a forcing period"
        );
        assert_eq!(
            sentence(&verdict(0.12, 1.0, 0.5, Validity::NotValid)),
            "not valid: the stop is soft, contacts last 12 % of a forcing period (the mean \
             impact speed differs by 0 %)"
        );
        let text = sentence(&verdict(0.002, 1.05, 0.553, Validity::NotValid));
        assert!(
            text.starts_with("not valid: the mean impact speed differs by 4.8 %"),
            "{text}"
        );
        assert!(
            text.ends_with(
                "the law realises e = 0.553, not the 0.5 asked: against a rigid stop at \
                 e = 0.553 the mean impact speed differs by 0 %"
            ),
            "{text}"
        );
        assert_eq!(
            gist(&verdict(0.2, 1.0, 0.5, Validity::NotValid)),
            "needs the compliant stop"
        );
        let mut resting = verdict(0.0082, 1.003, 0.5, Validity::Valid);
        resting.compliant_resting = Resting {
            phases: 4,
            fraction: 0.3,
        };
        resting.rigid_resting = Resting {
            phases: 1,
            fraction: 0.281,
        };
        assert!(
            sentence(&resting).ends_with(
                "contacts last 0.82 % of a forcing period; the body also rests on the stop 30 % \
                 of the time (4 resting phases, not counted as contacts; with the rigid stop \
                 28 %, 1 resting phase)"
            ),
            "{}",
            sentence(&resting)
        );
        resting.impacts.1 = 0;
        assert!(
            sentence(&resting).starts_with(
                "no impacts to compare: the compliant stop's body does not bounce here; the \
                 body also rests on the stop 30 %"
            ),
            "{}",
            sentence(&resting)
        );
    }
}
