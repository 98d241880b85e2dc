//! Headless EGL setup: enumerate EGL devices (`EGL_EXT_device_enumeration`), open a display on the
//! chosen one (`EGL_EXT_platform_device`), pick a config usable without any surface, and make a
//! compatibility-profile context current surfaceless (`EGL_KHR_surfaceless_context`).
//!
//! Design decision: the device platform, not the default display, so no X11/Wayland server or
//! DRM node is needed; the config template asks for an EMPTY surface type, because glutin's
//! default template asks for window surfaces and a device display has none. Mesa's software
//! device (`EGL_MESA_device_software`, llvmpipe) is preferred: deterministic, and what CI has.

use std::fmt;
use std::str::FromStr;

use glutin::api::egl::context::PossiblyCurrentContext;
use glutin::api::egl::device::Device;
use glutin::api::egl::display::Display;
use glutin::config::{Api, ConfigSurfaceTypes, ConfigTemplateBuilder};
use glutin::context::{ContextApi, ContextAttributesBuilder, GlProfile, Version};
use glutin::display::{GetDisplayExtensions, GlDisplay};
use glutin::error::ErrorKind;

use crate::Error;

/// What to install on Debian/Ubuntu for the Mesa EGL software device.
pub const INSTALL_HINT: &str =
    "install Mesa's EGL: apt-get install libegl1 libegl-mesa0 libgl1-mesa-dri";

/// The extension naming Mesa's software (llvmpipe) device.
const SOFTWARE_EXT: &str = "EGL_MESA_device_software";

/// Which EGL device the backend renders on.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub enum DeviceChoice {
    /// Mesa's software device if there is one, else the first device.
    #[default]
    Auto,
    /// The device at this index of EGL's enumeration (see [`list_devices`]).
    Index(usize),
    /// The first device whose name, vendor or extension list contains this text (case-insensitive).
    Name(String),
}

impl FromStr for DeviceChoice {
    type Err = std::convert::Infallible;

    /// `auto` (or empty), a decimal index, or any other text as a name substring.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        let s = s.trim();
        Ok(if s.is_empty() || s.eq_ignore_ascii_case("auto") {
            DeviceChoice::Auto
        } else if let Ok(i) = s.parse() {
            DeviceChoice::Index(i)
        } else {
            DeviceChoice::Name(s.to_owned())
        })
    }
}

/// One EGL device as enumerated.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct DeviceInfo {
    /// Position in EGL's enumeration.
    pub index: usize,
    /// `EGL_DEVICE_NAME` (if `EGL_EXT_device_query_name`), or "".
    pub name: String,
    /// `EGL_VENDOR` of the device, or "".
    pub vendor: String,
    /// The device's own extensions, sorted.
    pub extensions: Vec<String>,
    /// It advertises `EGL_MESA_device_software`.
    pub software: bool,
}

impl fmt::Display for DeviceInfo {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "#{} ", self.index)?;
        match (self.name.is_empty(), self.vendor.is_empty()) {
            (true, true) => write!(f, "(unnamed)")?,
            _ => write!(f, "{} {}", self.vendor, self.name)?,
        }
        if self.software {
            write!(f, " [software]")?;
        }
        Ok(())
    }
}

fn info(index: usize, d: &Device) -> DeviceInfo {
    let mut extensions: Vec<String> = d.extensions().iter().map(|e| e.to_string()).collect();
    extensions.sort();
    DeviceInfo {
        index,
        name: d.name().unwrap_or_default().to_owned(),
        vendor: d.vendor().unwrap_or_default().to_owned(),
        software: d.extensions().contains(SOFTWARE_EXT),
        extensions,
    }
}

fn query() -> Result<Vec<Device>, Error> {
    match Device::query_devices() {
        Ok(devices) => Ok(devices.collect()),
        Err(e) if e.error_kind() == ErrorKind::NotFound => Err(Error::Backend(format!(
            "libEGL (libEGL.so.1) could not be loaded; {INSTALL_HINT}"
        ))),
        Err(e) => Err(Error::Backend(format!(
            "EGL cannot enumerate devices ({e}); the EGL_EXT_device_enumeration and \
             EGL_EXT_platform_device client extensions are needed; {INSTALL_HINT}"
        ))),
    }
}

/// The EGL devices this machine offers, in EGL's order.
pub fn list_devices() -> Result<Vec<DeviceInfo>, Error> {
    Ok(query()?
        .iter()
        .enumerate()
        .map(|(i, d)| info(i, d))
        .collect())
}

/// The device `choice` names, with its description.
fn choose(choice: &DeviceChoice) -> Result<(Device, DeviceInfo), Error> {
    let devices = query()?;
    if devices.is_empty() {
        return Err(Error::Backend(format!(
            "EGL enumerates no device; Mesa's software device needs libegl-mesa0 and \
             libgl1-mesa-dri: {INSTALL_HINT}"
        )));
    }
    let infos: Vec<DeviceInfo> = devices
        .iter()
        .enumerate()
        .map(|(i, d)| info(i, d))
        .collect();
    let index = match choice {
        DeviceChoice::Auto => infos.iter().position(|d| d.software).unwrap_or(0),
        DeviceChoice::Index(i) => *i,
        DeviceChoice::Name(text) => {
            let t = text.to_lowercase();
            infos
                .iter()
                .position(|d| {
                    d.name.to_lowercase().contains(&t)
                        || d.vendor.to_lowercase().contains(&t)
                        || d.extensions.iter().any(|e| e.to_lowercase().contains(&t))
                })
                .unwrap_or(usize::MAX)
        }
    };
    match (devices.into_iter().nth(index), infos.get(index)) {
        (Some(device), Some(i)) => Ok((device, i.clone())),
        _ => {
            let list: Vec<String> = infos.iter().map(|d| d.to_string()).collect();
            Err(Error::Backend(format!(
                "no EGL device matches {choice:?}; devices: {}",
                list.join(", ")
            )))
        }
    }
}

/// A current, surfaceless, compatibility-profile EGL context on one device.
pub(super) struct EglContext {
    /// Kept alive (and current on this thread) for the backend's lifetime.
    pub context: PossiblyCurrentContext,
    pub display: Display,
    pub device: DeviceInfo,
}

impl fmt::Debug for EglContext {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("EglContext")
            .field("device", &self.device)
            .finish_non_exhaustive()
    }
}

/// Opens `choice`'s device and makes a GL 2.1+ compatibility context current on this thread.
pub(super) fn create(choice: &DeviceChoice) -> Result<EglContext, Error> {
    let (device, device_info) = choose(choice)?;
    // SAFETY: `device` comes from EGL's own enumeration; no native display handle is passed.
    let display = unsafe { Display::with_device(&device, None) }.map_err(|e| {
        Error::Backend(format!(
            "EGL device {device_info} cannot open a display ({e}); {INSTALL_HINT}"
        ))
    })?;
    let ext = display.extensions();
    let fail = |what: &str| {
        let mut exts: Vec<&str> = ext.iter().copied().collect();
        exts.sort_unstable();
        Error::Backend(format!(
            "EGL device {device_info} ({}): {what}; display extensions: {}",
            display.version_string(),
            exts.join(" ")
        ))
    };
    if !ext.contains("EGL_KHR_surfaceless_context") {
        return Err(fail(
            "EGL_KHR_surfaceless_context is missing, so no context can be current without a surface",
        ));
    }
    // An EMPTY surface type: a device display offers no window surfaces (glutin's default asks
    // for WINDOW), and the backend renders into its own FBO.
    let template = ConfigTemplateBuilder::new()
        .with_surface_type(ConfigSurfaceTypes::empty())
        .with_api(Api::OPENGL)
        .build();
    // SAFETY: plain attribute query on an initialised display.
    let config = unsafe { display.find_configs(template) }
        .ok()
        .and_then(|mut configs| configs.next())
        .ok_or_else(|| fail("no EGL config supports desktop OpenGL (EGL_OPENGL_BIT)"))?;
    let attributes = ContextAttributesBuilder::new()
        .with_context_api(ContextApi::OpenGl(Some(Version::new(2, 1))))
        .with_profile(GlProfile::Compatibility)
        .build(None);
    // SAFETY: `config` belongs to `display`.
    let context = unsafe { display.create_context(&config, &attributes) }.map_err(|e| {
        fail(&format!(
            "eglCreateContext for an OpenGL 2.1 compatibility-profile context failed ({e}); \
             the driver must support desktop GL with EGL_KHR_create_context's \
             EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT"
        ))
    })?;
    let context = context
        .make_current_surfaceless()
        .map_err(|e| fail(&format!("eglMakeCurrent without surfaces failed ({e})")))?;
    Ok(EglContext {
        context,
        display,
        device: device_info,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn device_choice_parses() {
        assert_eq!("auto".parse(), Ok(DeviceChoice::Auto));
        assert_eq!("".parse(), Ok(DeviceChoice::Auto));
        assert_eq!("2".parse(), Ok(DeviceChoice::Index(2)));
        assert_eq!(
            "llvmpipe".parse(),
            Ok(DeviceChoice::Name("llvmpipe".into()))
        );
    }
}
