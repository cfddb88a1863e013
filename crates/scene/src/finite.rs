//! Deserializers that refuse NaN and infinities where the number is read, so the parser reports
//! the exact line and column of the bad value.

use serde::de::{Deserialize, Deserializer, Error};

/// `(x, y, z)`: a vector or point as a scene file writes it, read finite by `finite3`.
pub type Triple = [f64; 3];

fn check<E: Error>(value: f64) -> Result<f64, E> {
    if value.is_finite() { Ok(value) } else { Err(E::custom(format!("number must be finite, got {value}"))) }
}

pub fn finite<'de, D: Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    check(f64::deserialize(d)?)
}

pub fn finite_option<'de, D: Deserializer<'de>>(d: D) -> Result<Option<f64>, D::Error> {
    Option::<f64>::deserialize(d)?.map(check::<D::Error>).transpose()
}

pub fn finite3<'de, D: Deserializer<'de>>(d: D) -> Result<Triple, D::Error> {
    let v = Triple::deserialize(d)?;
    for x in v {
        check::<D::Error>(x)?;
    }
    Ok(v)
}

pub fn finite_pairs<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<(f64, f64)>, D::Error> {
    let v = Vec::<(f64, f64)>::deserialize(d)?;
    for &(a, b) in &v {
        check::<D::Error>(a)?;
        check::<D::Error>(b)?;
    }
    Ok(v)
}

pub fn finite_velocity_table<'de, D: Deserializer<'de>>(d: D) -> Result<Vec<(f64, Triple)>, D::Error> {
    let v = Vec::<(f64, Triple)>::deserialize(d)?;
    for (t, w) in &v {
        check::<D::Error>(*t)?;
        for &x in w {
            check::<D::Error>(x)?;
        }
    }
    Ok(v)
}

/// An optional triple of finite numbers.
pub fn finite3_option<'de, D: Deserializer<'de>>(d: D) -> Result<Option<Triple>, D::Error> {
    let value = Option::<Triple>::deserialize(d)?;
    if let Some(v) = value
        && let Some(x) = v.iter().find(|x| !x.is_finite())
    {
        return Err(serde::de::Error::custom(format!("number must be finite, got {x}")));
    }
    Ok(value)
}
