//! The results tabs under the 3-D view (the WAI-ARIA tabs pattern): a `tablist` of buttons and
//! one `tabpanel` per [`Tab`]. Every panel stays mounted while hidden, so a run in one (planning,
//! a slice map, a lattice) goes on while another is shown. Which tab is open is part of the
//! page's [`crate::state::Settings`], kept in the address.

use leptos::prelude::*;
use wasm_bindgen::JsCast;

use crate::state::Tab;

/// The row of tabs. Click or Enter/Space opens a tab; with a tab focused, the arrow keys (left,
/// right, wrapping around), Home and End move the focus and open the tab they reach; only the open
/// tab is in the Tab order (roving tabindex), Tab moves on into its panel.
#[component]
pub fn TabList(open: Memo<Tab>, on_pick: impl Fn(Tab) + Copy + 'static) -> impl IntoView {
    let keydown = move |ev: leptos::ev::KeyboardEvent| {
        let Some(next) = open.get_untracked().after_key(&ev.key()) else { return };
        ev.prevent_default();
        on_pick(next);
        let button = web_sys::window()
            .and_then(|w| w.document())
            .and_then(|d| d.get_element_by_id(&tab_id(next)))
            .and_then(|e| e.dyn_into::<web_sys::HtmlElement>().ok());
        if let Some(b) = button {
            let _ = b.focus();
        }
    };
    view! {
        <div class="tablist" role="tablist" aria-label="results" data-testid="tablist" on:keydown=keydown>
            {Tab::ALL.map(|t| view! {
                <button
                    type="button"
                    role="tab"
                    id=tab_id(t)
                    data-tab=t.id()
                    aria-controls=panel_id(t)
                    aria-selected=move || (open.get() == t).to_string()
                    tabindex=move || if open.get() == t { "0" } else { "-1" }
                    on:click=move |_| on_pick(t)
                >
                    {t.label()}
                </button>
            })}
        </div>
    }
}

/// The panel of tab `of`: hidden unless it is `open`, its content mounted all along. Test
/// contract: `data-testid="panel-<id>"`.
#[component]
pub fn TabPanel(of: Tab, open: Memo<Tab>, #[prop(optional)] wide: bool, children: Children) -> impl IntoView {
    view! {
        <div
            class="panel"
            class:wide=wide
            role="tabpanel"
            id=panel_id(of)
            aria-labelledby=tab_id(of)
            data-testid=format!("panel-{}", of.id())
            tabindex="0"
            hidden=move || open.get() != of
        >
            {children()}
        </div>
    }
}

/// The element id of tab `t`'s button.
fn tab_id(t: Tab) -> String {
    format!("tab-{}", t.id())
}

/// The element id of tab `t`'s panel.
fn panel_id(t: Tab) -> String {
    format!("tabpanel-{}", t.id())
}
