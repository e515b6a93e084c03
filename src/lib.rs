//! Strider facade.
