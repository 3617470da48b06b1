//! A map cell out of time with nothing recorded (docs/maps.md §2): `unsettled` where the body
//! still impacted in the run's last tenth, `no-impact` where its impacts stopped long before —
//! two runs whose counts alone are alike (time limit, fewer impacts than the transient). The
//! time of the last impact that tells them apart is filled by both stops' runs, and the compliant
//! verdict's "the transient never ended" is the same notion.

use hertz_tui::model::ForceModel;
use hertz_tui::model::system::compliant::verdict::NothingRecorded;
use hertz_tui::model::system::map::{self, Agreement, Cause, MapOptions, Motion};
use hertz_tui::model::system::{
    CompliantDamping, Contact, EndReason, History, IMPACTING_AT_END, RunOptions, SystemModel,
    simulate,
};

use super::systems_common::{ball, bouncing_ball_preset, oscillator};

/// A cell's motion and its (first) run, with the map's defaults but `max_periods`.
fn cell(model: &SystemModel, contact: &Contact, max_periods: f64) -> (Motion, History) {
    let mut options = MapOptions::default();
    options.run.max_periods = max_periods;
    let motion = map::cell(model, contact, &options.run, &options).unwrap().0;
    (motion, simulate(model, contact, &options.run).unwrap())
}

/// Forcing periods from the last impact to the end of the run.
fn since_last(model: &SystemModel, h: &History) -> f64 {
    (h.end_state.t - h.last_impact.unwrap()) / model.spec.period()
}

#[test]
fn an_oscillator_whose_transient_impacts_stop_is_no_impact() {
    // ẍ + 0.02ẋ + x = 0.05 cos 0.5t: free amplitude 0.05/0.75 = 0.0667. A stop at 0.067 is
    // beyond it, but the start from rest overshoots: a few impacts, then free motion for ever.
    let far = oscillator(1.0, 0.02, 0.05, 0.5, 0.067, None, 0.8);
    let (motion, h) = cell(&far, &Contact::rigid(0.8), 20_000.0);
    // The counts are those of a transient that never ends: the time limit, nothing recorded,
    // some impacts but fewer than the transient's 300.
    assert_eq!(h.end, EndReason::TimeLimit);
    assert!(h.impacts.is_empty());
    assert!(
        h.impacts_total > 0 && h.impacts_total < 300,
        "{}",
        h.impacts_total
    );
    // Its impacts stopped within the first few forcing periods (5 of them in 4 measured).
    assert!(since_last(&far, &h) > 19_990.0, "{}", since_last(&far, &h));
    assert_eq!(motion, Motion::NoImpact);
    // Just inside the free amplitude it impacts for ever, once a forcing period.
    let near = oscillator(1.0, 0.02, 0.05, 0.5, 0.066, None, 0.8);
    assert_eq!(
        cell(&near, &Contact::rigid(0.8), 20_000.0).0,
        Motion::Periodic {
            impacts: 1,
            cycles: 1
        }
    );
}

#[test]
fn an_elastic_ball_climbing_ever_higher_is_unsettled() {
    // The rigid ball of e = 1 gains energy from the table (g = ω = 1): in 2000 forcing periods it
    // makes 90 to 222 of its 300 transient impacts (Γ = 3.5 to 2.5), still impacting at the end.
    for gamma in [1.5, 2.0, 2.5, 3.0, 3.5] {
        let model = ball(gamma, 1.0);
        let (motion, h) = cell(&model, &Contact::rigid(1.0), 2000.0);
        assert_eq!(h.end, EndReason::TimeLimit, "Γ = {gamma}");
        assert!(h.impacts.is_empty() && h.impacts_total < 300, "Γ = {gamma}");
        let since = since_last(&model, &h);
        // Its last flight is unfinished: measured 1.6 to 23 forcing periods, well inside the
        // last tenth (200).
        assert!(since < 30.0, "Γ = {gamma}: {since}");
        assert!(since < IMPACTING_AT_END * 2000.0);
        assert_eq!(motion, Motion::Unsettled, "Γ = {gamma}");
    }
}

/// The `bouncing-ball` preset's system.
fn preset_ball() -> SystemModel {
    let (scene, spec) = bouncing_ball_preset();
    SystemModel::from_scene(&scene, &spec).unwrap()
}

#[test]
fn the_last_impact_is_the_runs_last_for_both_stops() {
    // A run that records all its impacts ends on its last one: rigid and compliant alike.
    let model = preset_ball();
    let options = RunOptions {
        transient_impacts: 20,
        recorded_impacts: 10,
        ..RunOptions::default()
    };
    for contact in [
        Contact::rigid(model.restitution),
        Contact::Compliant {
            model: ForceModel::HuntCrossley,
            damping: CompliantDamping::PerImpact,
        },
    ] {
        let h = simulate(&model, &contact, &options).unwrap();
        assert_eq!(h.end, EndReason::Recorded, "{contact:?}");
        let last = h.impacts.last().unwrap().t;
        assert_eq!(h.last_impact, Some(last), "{contact:?}");
        // Nothing recorded, yet the transient's impacts are kept.
        let transient = simulate(
            &model,
            &contact,
            &RunOptions {
                transient_impacts: 1_000_000,
                max_periods: 50.0,
                ..options
            },
        )
        .unwrap();
        assert!(transient.impacts.is_empty(), "{contact:?}");
        let t = transient.last_impact.unwrap();
        assert!(t > 0.0 && t <= transient.end_state.t, "{contact:?}");
    }
}

#[test]
fn the_elastic_proposed_ball_is_unsettled_and_its_verdict_agrees() {
    // The proposed law with x_pl = 0 (the preset's) is elastic: the ball climbs ever higher on the
    // vibrating table and its run reaches 2000 forcing periods in its transient (docs/maps.md §2).
    let model = preset_ball();
    let proposed = Contact::Compliant {
        model: ForceModel::Proposed,
        damping: CompliantDamping::PerImpact,
    };
    let (motion, h) = cell(&model, &proposed, 2000.0);
    assert!(
        h.impacts.is_empty() && h.impacts_total > 0,
        "{}",
        h.impacts_total
    );
    assert!(since_last(&model, &h) < 200.0, "{}", since_last(&model, &h));
    assert_eq!(motion, Motion::Unsettled);
    // The verdict's "the transient never ended" is the same run read the same way.
    let mut run = MapOptions::default().run;
    run.max_periods = 2000.0;
    assert!(h.transient_unfinished(&run, model.spec.period()));
    assert!(matches!(
        NothingRecorded::of(&h, &run, model.spec.period()),
        Some(NothingRecorded::TransientUnfinished { .. })
    ));
    // The oscillator whose impacts stopped is not: its verdict would not say so either.
    let far = oscillator(1.0, 0.02, 0.05, 0.5, 0.067, None, 0.8);
    let (_, h) = cell(&far, &Contact::rigid(0.8), 20_000.0);
    let mut run = MapOptions::default().run;
    run.max_periods = 20_000.0;
    assert!(!h.transient_unfinished(&run, far.spec.period()));
    assert!(matches!(
        NothingRecorded::of(&h, &run, far.spec.period()),
        Some(NothingRecorded::NoBounce)
    ));
}

#[test]
fn unsettled_is_named_parsed_and_compared() {
    assert_eq!(Motion::Unsettled.name(), "unsettled");
    assert_eq!(Motion::parse("unsettled", None), Some(Motion::Unsettled));
    assert_eq!(Motion::parse("no-impact", None), Some(Motion::NoImpact));
    // Both stops unsettled: the same observation. One settled: not known, naming the other.
    let p1 = Motion::Periodic {
        impacts: 1,
        cycles: 1,
    };
    assert_eq!(
        Agreement::of(Motion::Unsettled, Motion::Unsettled),
        Agreement::Same
    );
    assert_eq!(Agreement::of(p1, Motion::Unsettled), Agreement::Unknown);
    assert_eq!(Agreement::of(Motion::Unsettled, p1), Agreement::Unknown);
    assert_eq!(
        Agreement::of(Motion::NoImpact, Motion::Unsettled),
        Agreement::Unknown
    );
    assert_eq!(
        Cause::unknown(p1, Motion::Unsettled)
            .map(Cause::words)
            .as_deref(),
        Some("the compliant stop's transient never ended")
    );
    assert_eq!(
        Cause::unknown(Motion::Unsettled, p1)
            .map(Cause::words)
            .as_deref(),
        Some("the rigid stop's transient never ended")
    );
    assert_eq!(Cause::unknown(Motion::Failed, Motion::Unsettled), None);
}

#[test]
fn a_ball_whose_flights_outgrow_a_map_step_is_unresolved_not_no_impact() {
    // The rigid ball of e = 1 from rest at Γ = 2 records its 64 impacts, no period; the exponent's
    // map then finds no impact within 64 forcing periods (its flights grow past that). It still
    // impacted at the end of its run: not `no-impact`.
    let model = ball(2.0, 1.0);
    let (motion, h) = cell(&model, &Contact::rigid(1.0), 20_000.0);
    assert_eq!(h.end, EndReason::Recorded);
    assert_eq!(h.impacts.len(), 64);
    assert_eq!(motion, Motion::Unresolved);
}
