//! The platform's mass and the winches' limits (scenario format 4, docs/dynamics.md): with a
//! mass the cables hold the platform's weight, and along a trajectory with a duration its
//! inertia; the winch limits bound every cable's speed and acceleration along timed motions.

use leptos::prelude::*;

use super::fields::{MatrixField, NumField, Vec3Field};
use super::Ed;
use crate::edit_logic::{self as el, Path};

/// The mass and winch part of the editor.
#[component]
pub fn TimingEditor(ed: Ed) -> impl IntoView {
    let dynamics = Path::of(&["robot", "dynamics"]);
    let winch = Path::of(&["robot", "winch"]);
    let has = Memo::new(move |_| ed.read(el::has_dynamics).unwrap_or(false));
    view! {
        <p class="hint">
            "With a mass the cables hold the platform's weight (put only outside loads in the wrench set); a trajectory with a duration (Trajectories) adds its inertia and the winch limits, and the results give its sections in seconds and how fast it may run."
        </p>
        <Show
            when=move || has.get()
            fallback=move || view! {
                <button type="button" data-testid="add-dynamics" on:click=move |_| ed.edit(el::add_dynamics)>
                    "Give the platform a mass"
                </button>
            }
        >
            <div class="dynamics" data-testid="dynamics">
                <NumField ed path=dynamics.k("mass") label="Mass" unit="kg" timed=true />
                <Vec3Field ed path=dynamics.k("com") label="Centre of mass (platform frame)" unit="m" />
                <MatrixField ed path=dynamics.k("inertia") rows=3 cols=3 label="Inertia about the centre of mass (kg·m², platform frame)" />
                <Vec3Field ed path=dynamics.k("gravity") label="Gravity (world frame)" unit="m/s²" />
                <button type="button" class="remove" data-testid="remove-dynamics" on:click=move |_| ed.edit(el::remove_dynamics)>
                    "Remove the mass"
                </button>
            </div>
        </Show>
        <div class="bounds">
            <NumField ed path=winch.k("speed") label="Winch speed limit |l̇|" unit="m/s" optional=true timed=true />
            <NumField ed path=winch.k("acceleration") label="Winch acceleration limit |l̈|" unit="m/s²" optional=true timed=true />
        </div>
    }
}
