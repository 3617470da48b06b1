//! `solve --format csv`: the trajectory of one impact as t,x,v,F rows (SI units).

use crate::model::impact::ImpactSolution;

/// `points` samples of the trajectory (plus its exact extrema) under the header `t,x,v,F`;
/// refuses to print a non-finite sample rather than write NaN into someone's plot.
pub fn render(solution: &ImpactSolution, points: usize) -> Result<String, String> {
    let mut out = String::from("t,x,v,F\n");
    for s in solution.trajectory.samples(points) {
        if ![s.t, s.x, s.v, s.f].iter().all(|x| x.is_finite()) {
            return Err(format!(
                "the {} trajectory has a non-finite sample at t = {:e} s",
                solution.summary.model, s.t
            ));
        }
        out.push_str(&format!("{:e},{:e},{:e},{:e}\n", s.t, s.x, s.v, s.f));
    }
    Ok(out)
}
