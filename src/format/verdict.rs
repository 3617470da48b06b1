//! The model's verdict "which approach does my system need?" (`system::compliant::verdict`) in
//! words with its numbers, for the command line and the explorer alike.

use crate::model::system::compliant::verdict::{LONG_CONTACT, Quantity, Validity, Verdict};

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
