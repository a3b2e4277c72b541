//! Shared test support: an independent reference model of cablenav's documented semantics
//! (`reference`), written from the definitions and not from `src/`; deterministic random
//! scenarios (`gen`); and the sampling checker that compares cablenav's reports with the
//! reference (`harness`).
#![allow(dead_code)]

pub mod gen;
pub mod harness;
pub mod reference;
