//! The compliant stop (issue 25, item 4; docs/systems.md): its period-doubling threshold of the
//! bouncing ball converges to the rigid closed form as contact time over forcing period falls —
//! for Hunt–Crossley with the exact χ at the asked e, for clamped Kelvin–Voigt at the e it
//! *realises*; every contact's energy balance closes; the elastic contact's peak force and
//! duration are Hertz's (eqs 5–7) where the system's forces are negligible during contact.

use std::f64::consts::PI;
use std::ops::ControlFlow;

use hertz_tui::format::verdict::sentence;
use hertz_tui::model::ForceModel;
use hertz_tui::model::force::ForceLaw;
use hertz_tui::model::presets::Registry;
use hertz_tui::model::system::compliant::estimate::hertz_estimate;
use hertz_tui::model::system::compliant::orbit::{MapPoint, period_doubling};
use hertz_tui::model::system::compliant::verdict::{Validity, verdict, verdict_of};
use hertz_tui::model::system::compliant::{CompliantOptions, CompliantStop, simulate_detailed};
use hertz_tui::model::system::{
    CompliantDamping, Contact, DiagramOptions, GuessStart, ImpactKind, ImpactRecord, OrbitGuess,
    OrbitOptions, Param, RunOptions, State, SystemKey, SystemKind, SystemModel, SystemSpec,
    bifurcation, find_orbit, simulate,
};

use super::systems_common::bouncing_ball_preset;

const E: f64 = 0.5;
const G: f64 = 9.81;

/// The ball at rest in the laboratory at t = 0, on the table's surface while the table moves up
/// at Aω: the table strikes it. These runs test the contacts, not the start; from rest on the
/// table (the default of both stops) they settle on other attractors.
const STRUCK: Option<State> = Some(State {
    t: 0.0,
    x: 0.0,
    v: 0.0,
});

/// Γ_PD = √(Γ_SN² + (2(1+e²)/(1+e)²)²), Γ_SN = π(1−e)/(1+e): the rigid bouncing ball's period-1
/// orbit loses stability there (exact impact map; docs/physics.md, bouncing ball).
fn rigid_threshold(e: f64) -> f64 {
    let sn = PI * (1.0 - e) / (1.0 + e);
    let b = 2.0 * (1.0 + e * e) / (1.0 + e).powi(2);
    (sn * sn + b * b).sqrt()
}

/// The steel sphere R = 10 mm on a steel plate, bouncing on a table at `frequency` with Γ.
fn ball(frequency: f64, gamma: f64) -> SystemModel {
    let mut scene = Registry::builtin()
        .unwrap()
        .scene("steel-sphere-r10-plate")
        .unwrap();
    scene.impact.restitution = E;
    let omega = 2.0 * PI * frequency;
    let spec = SystemSpec {
        kind: SystemKind::BouncingBall {
            amplitude: gamma * G / (omega * omega),
            frequency,
            gravity: G,
        },
    };
    SystemModel::from_scene(&scene, &spec).unwrap()
}

fn stop(model: &SystemModel, law: ForceModel, damping: CompliantDamping) -> CompliantStop {
    let options = CompliantOptions {
        rtol: 1e-12,
        ..CompliantOptions::default()
    };
    CompliantStop::new(model, law, damping, options).unwrap()
}

/// The rigid period-1 orbit at Γ: impact speed gT/(1+e), table velocity u(1−e)/(1+e) with u = gT/2.
fn rigid_orbit(frequency: f64, gamma: f64, e: f64) -> MapPoint {
    let period = 1.0 / frequency;
    let omega = 2.0 * PI * frequency;
    let amplitude = gamma * G / (omega * omega);
    let u = G * period / 2.0;
    let phase = (u * (1.0 - e) / ((1.0 + e) * amplitude * omega)).acos();
    MapPoint {
        t: phase / omega,
        v_in: G * period / (1.0 + e),
        stop: 0,
    }
}

/// The compliant period-doubling threshold near the rigid one at `e_rigid`.
fn compliant_threshold(
    frequency: f64,
    law: ForceModel,
    damping: CompliantDamping,
    e_rigid: f64,
) -> f64 {
    let rigid = rigid_threshold(e_rigid);
    period_doubling(
        |gamma| Ok(stop(&ball(frequency, gamma), law, damping)),
        rigid_orbit(frequency, 0.99 * rigid, e_rigid),
        (1, 1),
        (0.9 * rigid, 1.03 * rigid),
    )
    .unwrap()
    .expect("a sign change of 1 + tr J + det J")
}

/// The forcing frequency at which the ball's elastic contact at the rigid orbit's impact speed
/// gT/(1+e) lasts `ratio` of the period (eq 7: t_c ∝ v^(−1/5)).
fn frequency_for_ratio(ratio: f64) -> f64 {
    let model = ball(20.0, 1.0);
    let s = stop(&model, ForceModel::Quasistatic, CompliantDamping::PerImpact);
    let c1 = s.elastic.contact_time(model.mass, 1.0);
    // ratio = c1·(g/((1+e)f))^(−1/5)·f  ⇒  f = (ratio/c1·(g/(1+e))^(1/5))^(5/6).
    (ratio / c1 * (G / (1.0 + E)).powf(0.2)).powf(5.0 / 6.0)
}

#[test]
fn hunt_crossley_with_the_exact_chi_converges_to_the_rigid_threshold() {
    let rigid = rigid_threshold(E);
    let mut deviations = Vec::new();
    for ratio in [0.1, 0.03, 0.01, 0.003] {
        let f = frequency_for_ratio(ratio);
        let gamma = compliant_threshold(
            f,
            ForceModel::HuntCrossley,
            CompliantDamping::CalibratedTo(E),
            E,
        );
        deviations.push((ratio, gamma / rigid - 1.0));
    }
    eprintln!("Hunt–Crossley exact χ, (t_c/T, ΔΓ_PD/Γ_PD): {deviations:?}");
    // The figures: about −1.4 % at t_c/T = 0.1, −0.1 % at 0.003.
    let at = |r: f64| deviations.iter().find(|d| d.0 == r).unwrap().1;
    assert!((-0.025..-0.005).contains(&at(0.1)), "{deviations:?}");
    assert!(at(0.003).abs() < 0.003, "{deviations:?}");
    for pair in deviations.windows(2) {
        assert!(
            pair[1].1.abs() < pair[0].1.abs(),
            "not converging: {deviations:?}"
        );
    }
}

#[test]
fn clamped_kelvin_voigt_converges_to_the_rigid_threshold_at_its_realised_e() {
    // The law's own e: its exact impact (docs/physics.md §6.3) at the scene's v₀.
    let model = ball(20.0, 1.0);
    let s = stop(
        &model,
        ForceModel::with_id("kelvin-voigt"),
        CompliantDamping::PerImpact,
    );
    let law = s.source.at(1.0).unwrap();
    let exact = law.exact(1e-12).unwrap();
    let realised = exact.v_out / s.source.base().v0;
    assert!((realised - 0.55).abs() < 0.01, "{realised}");
    let t_c = exact.t_contact;
    let mut deviations = Vec::new();
    for ratio in [0.03, 0.003] {
        let f = ratio / t_c;
        let gamma = compliant_threshold(
            f,
            ForceModel::with_id("kelvin-voigt"),
            CompliantDamping::PerImpact,
            realised,
        );
        deviations.push((
            ratio,
            gamma / rigid_threshold(realised) - 1.0,
            gamma / rigid_threshold(E) - 1.0,
        ));
    }
    eprintln!(
        "clamped Kelvin–Voigt, (t_c/T, vs rigid at realised e, vs rigid at asked e): {deviations:?}"
    );
    let last = deviations[1];
    assert!(last.1.abs() < 0.003, "{deviations:?}");
    // ...and far from the rigid answer at the e it was asked for (the issue: −7.4 %).
    assert!(last.2 < -0.05, "{deviations:?}");
    assert!(
        deviations[1].1.abs() < deviations[0].1.abs(),
        "{deviations:?}"
    );
}

#[test]
fn every_contact_closes_its_energy_balance_and_elastic_contacts_are_hertz() {
    let model = ball(20.0, 2.0);
    let options = RunOptions {
        transient_impacts: 5,
        recorded_impacts: 30,
        initial: STRUCK,
        ..RunOptions::default()
    };
    let compliant = CompliantOptions::default();
    for law in [
        ForceModel::HuntCrossley,
        ForceModel::with_id("kelvin-voigt"),
        ForceModel::Proposed,
        ForceModel::DryFriction,
    ] {
        let run = simulate_detailed(
            &model,
            law,
            CompliantDamping::PerImpact,
            &options,
            compliant,
        )
        .unwrap();
        assert_eq!(run.history.impacts.len(), 30, "{law}");
        for (impact, detail) in run.history.impacts.iter().zip(&run.details) {
            assert!(detail.energy.closure() < 1e-6, "{law}: {detail:?}");
            // Dissipative laws never return more than they took (beyond the closure).
            assert!(
                detail.energy.lost() > -1e-6 * detail.energy.incoming,
                "{law}: {detail:?}"
            );
            assert!(
                impact.v_out <= impact.v_in * 1.001 + 1e-9,
                "{law}: {impact:?}"
            );
        }
    }
    // Elastic Hertz: with g·t_c ≪ v_in the contact is the free impact of eqs 5–7.
    let run = simulate_detailed(
        &model,
        ForceModel::Quasistatic,
        CompliantDamping::PerImpact,
        &options,
        compliant,
    )
    .unwrap();
    let law = stop(&model, ForceModel::Quasistatic, CompliantDamping::PerImpact).elastic;
    for impact in &run.history.impacts {
        let hertz = hertz_estimate(&law, model.mass, impact.v_in).unwrap();
        let f = impact.peak_force.unwrap();
        let t_c = impact.contact_time.unwrap();
        // Gravity and the table's acceleration act over t_c: their share of the momentum is
        // (g + Aω²)·t_c / v_in, below 1e-3 here.
        assert!(
            (f / hertz.peak_force - 1.0).abs() < 2e-3,
            "{impact:?} {hertz:?}"
        );
        assert!(
            (t_c / hertz.contact_time - 1.0).abs() < 2e-3,
            "{impact:?} {hertz:?}"
        );
    }
}

#[test]
fn the_verdict_follows_contact_time_over_period_and_the_realised_e() {
    // Γ = 1.3: both stops settle on the period-1 orbit when started on the rigid one (just after
    // its impact); from rest they may chatter and stick instead.
    let on_orbit = |frequency: f64| {
        let p = rigid_orbit(frequency, 1.3, E);
        let omega = 2.0 * PI * frequency;
        let amplitude = 1.3 * G / (omega * omega);
        RunOptions {
            transient_impacts: 60,
            recorded_impacts: 40,
            initial: Some(State {
                t: p.t,
                x: amplitude * (omega * p.t).sin(),
                v: amplitude * omega * (omega * p.t).cos() + E * p.v_in,
            }),
            ..RunOptions::default()
        }
    };
    let f = frequency_for_ratio(0.003);
    let run = on_orbit(f);
    let short = ball(f, 1.3);
    let v = verdict(
        &short,
        ForceModel::HuntCrossley,
        CompliantDamping::CalibratedTo(E),
        &run,
    )
    .unwrap();
    eprintln!("{v:?}\n{}", sentence(&v));
    assert_eq!(v.validity, Validity::Valid, "{v:?}");
    assert!((v.contact_ratio / 0.003 - 1.0).abs() < 0.3, "{v:?}");
    assert!((v.realised_restitution - E).abs() < 0.005, "{v:?}");
    assert!(
        v.comparisons.iter().all(|c| c.relative().abs() < 0.01),
        "{v:?}"
    );

    let f = frequency_for_ratio(0.1);
    let long = ball(f, 1.3);
    let v = verdict(
        &long,
        ForceModel::HuntCrossley,
        CompliantDamping::CalibratedTo(E),
        &on_orbit(f),
    )
    .unwrap();
    eprintln!("{v:?}\n{}", sentence(&v));
    assert_eq!(v.validity, Validity::NotValid, "{v:?}");
    assert!(
        sentence(&v).starts_with("not valid: the stop is soft"),
        "{}",
        sentence(&v)
    );

    // Clamped Kelvin–Voigt realises more than the e = 0.5 it was asked for, and says so.
    let v = verdict(
        &short,
        ForceModel::with_id("kelvin-voigt"),
        CompliantDamping::PerImpact,
        &run,
    )
    .unwrap();
    eprintln!("{v:?}\n{}", sentence(&v));
    assert!((v.realised_restitution - 0.553).abs() < 0.01, "{v:?}");
    assert_ne!(v.validity, Validity::Valid, "{v:?}");
    let decisive = v.comparisons[v.decisive];
    assert!(decisive.relative_at_realised().abs() < 0.01, "{v:?}");
    assert!(
        sentence(&v).contains("the law realises e = 0.55"),
        "{}",
        sentence(&v)
    );
}

#[test]
fn orbits_and_diagrams_dispatch_on_the_compliant_contact_and_meet_the_rigid_ones() {
    // Short contacts (t_c/T = 0.003), Γ = 1.3: the period-1 orbit of both stops.
    let f = frequency_for_ratio(0.003);
    let model = ball(f, 1.3);
    let hc = Contact::Compliant {
        model: ForceModel::HuntCrossley,
        damping: CompliantDamping::CalibratedTo(E),
    };
    let p = rigid_orbit(f, 1.3, E);
    let guess = OrbitGuess {
        forcing_cycles: 1,
        impacts: 1,
        start: Some(GuessStart {
            phase: 2.0 * PI * f * p.t,
            v_in: p.v_in,
            stop: 0,
        }),
        attractor: RunOptions::default(),
    };
    let compliant = find_orbit(&model, &hc, &guess, &OrbitOptions::default()).unwrap();
    let rigid = find_orbit(&model, &Contact::rigid(E), &guess, &OrbitOptions::default()).unwrap();
    assert!(compliant.stable && rigid.stable);
    let (c, r) = (&compliant.points[0], &rigid.points[0]);
    assert!((c.v_in / r.v_in - 1.0).abs() < 2e-3, "{c:?} {r:?}");
    // det J = e² for the rigid map (docs/physics.md §8.1); the compliant map's is near it.
    assert!((rigid.jacobian_det - E * E).abs() < 1e-8, "{rigid:?}");
    assert!(
        (compliant.jacobian_det / (E * E) - 1.0).abs() < 0.02,
        "{compliant:?}"
    );
    for (a, b) in compliant.multipliers.iter().zip(&rigid.multipliers) {
        assert!(
            (a.norm() - b.norm()).abs() < 0.02,
            "{compliant:?} {rigid:?}"
        );
    }

    // A small diagram through the same entry point: period 1 at every value, the compliant
    // columns' impact speeds within 0.5 % of the rigid ones.
    let omega = 2.0 * PI * f;
    let amplitude = 1.3 * G / (omega * omega);
    let options = DiagramOptions {
        run: RunOptions {
            transient_impacts: 60,
            recorded_impacts: 10,
            initial: Some(State {
                t: p.t,
                x: amplitude * (omega * p.t).sin(),
                v: amplitude * omega * (omega * p.t).cos() + E * p.v_in,
            }),
            ..RunOptions::default()
        },
        chunk: 3,
        ..DiagramOptions::default()
    };
    let values = [1.25, 1.3, 1.35];
    let run = |contact: &Contact| {
        bifurcation(
            &model,
            contact,
            Param::System(SystemKey::Gamma),
            &values,
            &options,
            |_| ControlFlow::Continue(()),
        )
        .unwrap()
    };
    let (d_rigid, d_compliant) = (run(&Contact::rigid(E)), run(&hc));
    for (a, b) in d_rigid.columns.iter().zip(&d_compliant.columns) {
        assert_eq!(b.velocities.len(), 10, "{b:?}");
        let (va, vb) = (a.velocities[9], b.velocities[9]);
        assert!((vb / va - 1.0).abs() < 5e-3, "Γ = {}: {va} {vb}", a.value);
    }
}

/// The `bouncing-ball` preset (steel sphere R = 10 mm on a steel table, 20 Hz) at amplitude `a`.
fn preset_ball(amplitude: f64) -> SystemModel {
    let (scene, mut spec) = bouncing_ball_preset();
    if let SystemKind::BouncingBall { amplitude: a, .. } = &mut spec.kind {
        *a = amplitude;
    }
    SystemModel::from_scene(&scene, &spec).unwrap()
}

#[test]
fn the_verdict_weighs_the_impacts_contacts_and_reports_resting_phases_apart() {
    let hc = ForceModel::HuntCrossley;
    let options = RunOptions {
        initial: STRUCK,
        ..RunOptions::default()
    };
    // The preset as it is (Γ = 1.61): the ball bounces, and now and then settles on the table and
    // rides it until the table's deceleration exceeds g. Those contacts last a large part of a
    // period; the impacts' own contacts are Hertz's (eq 7) at their speeds, about 100 µs.
    let model = preset_ball(1e-3);
    let h = simulate_detailed(
        &model,
        hc,
        CompliantDamping::PerImpact,
        &options,
        CompliantOptions::default(),
    )
    .unwrap()
    .history;
    let period = model.spec.period();
    let s = stop(&model, hc, CompliantDamping::PerImpact);
    let hertz = |v: f64| {
        hertz_estimate(&s.elastic, model.mass, v)
            .unwrap()
            .contact_time
    };
    let (impacts, rests): (Vec<&ImpactRecord>, Vec<&ImpactRecord>) =
        h.impacts.iter().partition(|i| i.kind == ImpactKind::Impact);
    assert!(impacts.len() > 150 && !rests.is_empty(), "{h:?}");
    for i in &impacts {
        // Hunt–Crossley's own χ at e = 0.5 lengthens the elastic contact by about 10 %; the
        // table and gravity a little more at the slowest impacts.
        let ratio = i.contact_time.unwrap() / hertz(i.v_in);
        assert!((0.95..1.4).contains(&ratio), "{i:?}: t_c/t_Hertz = {ratio}");
    }
    for r in &rests {
        assert!(r.contact_time.unwrap() > 10.0 * hertz(r.v_in), "{r:?}");
        assert!(
            h.sticks
                .iter()
                .any(|s| s.start == r.t && s.end == Some(r.t + r.contact_time.unwrap())),
            "each resting contact is a sticking phase: {r:?} {:?}",
            h.sticks
        );
    }
    let v = verdict_of(&model, hc, &options, &h, None).unwrap();
    let longest = impacts
        .iter()
        .map(|i| i.contact_time.unwrap())
        .fold(0.0, f64::max);
    assert_eq!(v.contact_time, longest);
    // Of the order of eq 7 at the impacts' speeds: between t_c at the fastest and 1.4 t_c at the
    // slowest, all under 1 % of the period here (the resting contacts last up to 19 % of it).
    let (slow, fast) = impacts.iter().fold((f64::INFINITY, 0.0_f64), |(a, b), i| {
        (a.min(i.v_in), b.max(i.v_in))
    });
    assert!(
        v.contact_ratio >= hertz(fast) / period && v.contact_ratio <= 1.4 * hertz(slow) / period,
        "{v:?}"
    );
    assert!(v.contact_ratio < 0.01, "{v:?}");
    let longest_rest = rests
        .iter()
        .map(|r| r.contact_time.unwrap())
        .fold(0.0, f64::max);
    assert!(longest_rest / period > 0.1, "{longest_rest}");
    assert_eq!(v.compliant_resting.phases, rests.len());
    assert!(v.compliant_resting.fraction > 0.0 && v.compliant_resting.fraction < 0.05);
    assert_eq!(v.impacts.1, impacts.len());
    // The verdict from the caller's run is the verdict that runs it itself.
    assert_eq!(
        verdict(&model, hc, CompliantDamping::PerImpact, &options).unwrap(),
        v
    );
    let text = sentence(&v);
    assert!(text.contains("the body also rests on the stop"), "{text}");

    // Γ = 1.1: the ball spends most of each period riding the table, with either stop.
    let omega = model.spec.omega();
    let model = preset_ball(1.1 * 9.80665 / (omega * omega));
    let h = simulate(
        &model,
        &Contact::Compliant {
            model: hc,
            damping: CompliantDamping::PerImpact,
        },
        &options,
    )
    .unwrap();
    let v = verdict_of(&model, hc, &options, &h, None).unwrap();
    assert!(v.contact_ratio < 0.01, "{v:?}");
    assert!(v.compliant_resting.fraction > 0.5, "{v:?}");
    assert!(v.rigid_resting.fraction > 0.5, "{v:?}");

    // Γ = 0.9: the ball never leaves the table: no impacts, resting for good.
    let model = preset_ball(0.9 * 9.80665 / (omega * omega));
    let v = verdict(&model, hc, CompliantDamping::PerImpact, &options).unwrap();
    assert_eq!((v.impacts.1, v.contact_time), (0, 0.0), "{v:?}");
    assert_eq!(v.compliant_resting.fraction, 1.0, "{v:?}");
    assert!(
        sentence(&v).starts_with("no impacts to compare"),
        "{}",
        sentence(&v)
    );
}

#[test]
fn a_compliant_orbit_is_found_without_a_start_where_the_run_from_rest_settles() {
    // Γ = 1.3, t_c/T = 0.003: the run from rest chatters and rests on the table; the search
    // starts Newton from the rigid orbit and lands on the compliant one beside it.
    let f = frequency_for_ratio(0.003);
    let model = ball(f, 1.3);
    let hc = Contact::Compliant {
        model: ForceModel::HuntCrossley,
        damping: CompliantDamping::CalibratedTo(E),
    };
    let run = simulate(&model, &hc, &RunOptions::default()).unwrap();
    assert!(
        run.impacts.iter().any(|i| i.kind == ImpactKind::Rest),
        "{:?}",
        run.end
    );
    let guess = OrbitGuess {
        forcing_cycles: 1,
        impacts: 1,
        start: None,
        attractor: RunOptions::default(),
    };
    let o = find_orbit(&model, &hc, &guess, &OrbitOptions::default()).unwrap();
    assert!(o.stable, "{o:?}");
    let v_rigid = G / f / (1.0 + E);
    assert!((o.points[0].v_in / v_rigid - 1.0).abs() < 2e-3, "{o:?}");
}

#[test]
fn compliant_multipliers_reach_the_rigid_det_j_and_agree_with_a_finer_tolerance_to_1e_10() {
    use hertz_tui::model::system::compliant::orbit::{map_jacobian_extrapolated, newton};
    // The period-1 orbit at Γ = 1.3 with Hunt–Crossley at the exact χ: det J → e² (the rigid
    // map's, docs/physics.md §8.1) linearly in t_c/T; the extrapolated Jacobian at the orbits'
    // rtol 1e-12 against one at 1e-13 agrees to ~1e-11 (plain central differences at a step of
    // 1e-6: ~1e-10, measured 7e-11 to 1.5e-10 on these orbits).
    let mut deviations = Vec::new();
    for ratio in [0.01, 0.003, 0.001] {
        let f = frequency_for_ratio(ratio);
        let model = ball(f, 1.3);
        let at = |rtol: f64| {
            let options = CompliantOptions {
                rtol,
                ..CompliantOptions::default()
            };
            let s = CompliantStop::new(
                &model,
                ForceModel::HuntCrossley,
                CompliantDamping::CalibratedTo(E),
                options,
            )
            .unwrap();
            let (p, _) = newton(&s, rigid_orbit(f, 1.3, E), 1, 1, 1e-11, 40).unwrap();
            map_jacobian_extrapolated(&s, p, 1).unwrap()
        };
        let (j, fine) = (at(1e-12), at(1e-13));
        assert!(
            (j.determinant() - fine.determinant()).abs() < 3e-11
                && (j.trace() - fine.trace()).abs() < 3e-11,
            "t_c/T = {ratio}: {j} against {fine}"
        );
        let deviation = E * E - fine.determinant();
        assert!(
            deviation > 0.0 && deviation < 0.06 * ratio,
            "{ratio}: {deviation}"
        );
        deviations.push(deviation);
    }
    eprintln!("e² − det J at t_c/T 0.01, 0.003, 0.001: {deviations:?}");
    // Linear in t_c/T: each step down by 3.3 divides it by about that.
    for w in deviations.windows(2) {
        let r = w[1] / w[0];
        assert!((0.2..0.45).contains(&r), "{deviations:?}");
    }
}

#[test]
fn plastic_dents_are_each_contacts_own_and_are_not_carried_to_the_next() {
    // Thornton's law yields at the preset ball's impact speeds: each contact leaves the dent of a
    // free Thornton impact at its own v_in from an undeformed stop (its closed form), summed in
    // History::dents but not carried; viscoelastic and elastic laws leave no permanent dent.
    let model = preset_ball(1e-3);
    let options = RunOptions {
        transient_impacts: 100,
        recorded_impacts: 40,
        initial: STRUCK,
        ..RunOptions::default()
    };
    let run = |law: ForceModel| {
        simulate_detailed(
            &model,
            law,
            CompliantDamping::PerImpact,
            &options,
            CompliantOptions::default(),
        )
        .unwrap()
    };
    let thornton = ForceModel::with_id("thornton");
    let r = run(thornton);
    let base = *stop(&model, thornton, CompliantDamping::PerImpact)
        .source
        .base();
    let mut sum = 0.0;
    let mut dented = 0;
    for (i, d) in r.history.impacts.iter().zip(&r.details) {
        if i.kind != ImpactKind::Impact || d.residual == 0.0 {
            continue;
        }
        let law = thornton
            .law(&hertz_tui::model::force::ImpactParams { v0: i.v_in, ..base })
            .unwrap();
        let exact = law.exact(1e-12).unwrap();
        // The table and gravity act during the ~100 µs contact: their impulse (g + Aω²)·t_c is
        // about 7e-3 of v_in at the fastest impacts, and the dent moves by a part of that.
        assert!(
            (d.residual / exact.x_residual - 1.0).abs() < 1e-2,
            "v_in {}: {} against {}",
            i.v_in,
            d.residual,
            exact.x_residual
        );
        sum += d.residual;
        dented += 1;
    }
    let dents = r.history.dents;
    assert!(dented > 20, "{dents:?}");
    assert_eq!(dents.contacts, dented);
    assert!((dents.total / sum - 1.0).abs() < 1e-12, "{dents:?} {sum}");
    for law in [
        ForceModel::HuntCrossley,
        ForceModel::with_id("kelvin-voigt"),
    ] {
        let r = run(law);
        assert_eq!(r.history.dents.contacts, 0, "{law:?}");
        if law != ForceModel::HuntCrossley {
            assert!(
                r.details.iter().any(|d| d.residual > 0.0),
                "clamped: it lets go inside"
            );
        }
    }
}
