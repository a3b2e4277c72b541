//! The short help panel: what is checked, what the colours mean, and the conventions.

use leptos::prelude::*;

/// The help panel (a `<details>`, closed at first).
#[component]
pub fn Help() -> impl IntoView {
    view! {
        <details class="help" data-testid="help">
            <summary>"Help: conditions, colours, conventions"</summary>
            <h3>"What is checked"</h3>
            <ul>
                <li>
                    <strong>"Cable–cable: "</strong>
                    "every two cables stay at least the cable–cable clearance apart (centrelines; cables that \
                     share an anchor are not compared)."
                </li>
                <li>
                    <strong>"Cable–obstacle: "</strong>
                    "every cable stays at least the cable–obstacle clearance from every obstacle's surface."
                </li>
                <li><strong>"Cable length: "</strong>"each cable's length stays within its [min, max] (m)."</li>
                <li>
                    <strong>"Wrench (6 cables): "</strong>
                    "the cables can hold every wrench of the ellipsoid {w : (w − w₀)ᵀE(w − w₀) ≤ 1} with each \
                     tension within its [min, max] (N)."
                </li>
            </ul>
            <p>
                "Verification is exact: the boundaries are roots of polynomials, isolated with certified \
                 error bounds, not samples."
            </p>
            <h3>"Colours"</h3>
            <p>
                <span class="swatch feasible"></span>"feasible "
                <span class="swatch infeasible"></span>"infeasible (a condition is violated) "
                <span class="swatch uncertain"></span>"uncertain (the core could not decide). "
                "A field with a red border holds something the core or the form cannot accept; the message \
                 under it says why."
            </p>
            <h3>"Conventions"</h3>
            <ul>
                <li>"Units: metres, newtons, radians — except XYZ Euler angles, in degrees."</li>
                <li>
                    <strong>"Tilt-and-torsion (φ, θ, σ): "</strong>
                    "R = Rz(φ)·Ry(θ)·Rz(σ − φ). θ tilts the platform's z axis away from the world's, φ is the \
                     direction (azimuth) of that tilt, σ the torsion about the tilted axis. At θ = 0 only σ matters."
                </li>
                <li><strong>"XYZ Euler (α, β, γ), degrees: "</strong>"R = Rx(α)·Ry(β)·Rz(γ), about the moving axes."</li>
                <li><strong>"Quaternion: "</strong>"[w, x, y, z], scalar first."</li>
                <li>
                    <strong>"point_frame: "</strong>
                    "where the wrench acts. “platform”: the point turns with the platform (c = p + R·point); \
                     “world”: the offset stays parallel to the world axes (c = p + point). The wrench components \
                     are always along the world axes."
                </li>
                <li>
                    <strong>"Trajectories: "</strong>
                    "the position is a polynomial in τ ∈ [0, 1], the orientation a slerp in t ∈ [0, 1] between \
                     Qs and Qe (cos θ = Qs·Qe; τ = tan(tθ/2)/tan(θ/2), so τ and t agree at the ends). Via \
                     points sit at τ = k/(n−1)."
                </li>
            </ul>
            <h3>"Sharing"</h3>
            <p>
                "The address bar holds the scenario (compressed); edits are also saved in this browser. Add "
                <code>"?embed=1"</code>
                " to a link for a compact view without the editor, for an iframe in a course page."
            </p>
        </details>
    }
}
