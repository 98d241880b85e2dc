//! Key and mouse events in the shape of AWT's `KeyEvent` and `MouseEvent` (what JOGL listeners
//! receive), made from winit's events. Design decision: fixedgl's own small types, not winit's, so
//! that a listener does not depend on winit's version, and so that keys compare the way JOGL code
//! compares `VK_` codes (a letter key is the same key with or without Shift).

use winit::event::{ElementState, MouseButton as WinitButton};
use winit::keyboard::{Key as WinitKey, NamedKey};

/// A key, as `KeyEvent.getKeyCode()` names it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Key {
    /// A key that produces a character: letters in lower case whatever Shift or Caps Lock say
    /// (`VK_A` is one key), every other character as the layout gives it (`'+'`, `'1'`, `'/'`).
    Char(char),
    /// Escape.
    Escape,
    /// Enter / Return.
    Enter,
    /// The space bar.
    Space,
    /// Tab.
    Tab,
    /// Backspace.
    Backspace,
    /// Delete.
    Delete,
    /// Insert.
    Insert,
    /// Home.
    Home,
    /// End.
    End,
    /// Page Up.
    PageUp,
    /// Page Down.
    PageDown,
    /// Arrow left.
    Left,
    /// Arrow right.
    Right,
    /// Arrow up.
    Up,
    /// Arrow down.
    Down,
    /// A function key, F1 to F24.
    F(u8),
    /// Either Shift key.
    Shift,
    /// Either Control key.
    Control,
    /// Either Alt key.
    Alt,
    /// The Super / Windows / Command key.
    Super,
    /// Any other key.
    Other,
}

/// Modifier keys held during an event.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Modifiers {
    /// Shift.
    pub shift: bool,
    /// Control.
    pub control: bool,
    /// Alt.
    pub alt: bool,
    /// Super / Windows / Command.
    pub logo: bool,
}

/// A key event (JOGL listeners: `java.awt.event.KeyEvent`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct KeyEvent {
    /// The key (`getKeyCode`).
    pub key: Key,
    /// The character the press typed, with Shift and the layout applied (`getKeyChar`); `None` for
    /// keys that type nothing (arrows, F keys, modifiers) and for releases.
    pub text: Option<char>,
    /// True for the automatic repeats of a held key.
    pub repeat: bool,
    /// Modifiers held.
    pub modifiers: Modifiers,
}

/// A mouse button.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum MouseButton {
    /// `BUTTON1`.
    Left,
    /// `BUTTON2`.
    Middle,
    /// `BUTTON3`.
    Right,
    /// Any other button (back, forward, ...), by the window system's number.
    Other(u16),
}

/// The set of mouse buttons held.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct MouseButtons {
    /// The left button.
    pub left: bool,
    /// The middle button.
    pub middle: bool,
    /// The right button.
    pub right: bool,
}

impl MouseButtons {
    /// Whether any of the three is held.
    pub fn any(&self) -> bool {
        self.left || self.middle || self.right
    }

    pub(crate) fn set(&mut self, button: MouseButton, down: bool) {
        match button {
            MouseButton::Left => self.left = down,
            MouseButton::Middle => self.middle = down,
            MouseButton::Right => self.right = down,
            MouseButton::Other(_) => {}
        }
    }
}

/// A mouse event (JOGL listeners: `java.awt.event.MouseEvent` and `MouseWheelEvent`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct MouseEvent {
    /// Pointer x in pixels from the window's left edge (`getX`).
    pub x: f64,
    /// Pointer y in pixels from the window's top edge (`getY`; GL's window y is `height - 1 - y`).
    pub y: f64,
    /// The button that went down or up (`getButton`); for moves and drags, `None`.
    pub button: Option<MouseButton>,
    /// The buttons held after this event.
    pub buttons: MouseButtons,
    /// Wheel notches (`getWheelRotation`): positive towards the user (scrolling down), as AWT;
    /// 0 except in `mouse_wheel_moved`. Fractional for touchpads.
    pub wheel_rotation: f64,
    /// Modifiers held.
    pub modifiers: Modifiers,
}

/// fixedgl's key for winit's logical key.
pub(crate) fn key(logical: &WinitKey) -> Key {
    match logical {
        WinitKey::Character(s) => {
            let mut chars = s.chars();
            match (chars.next(), chars.next()) {
                (Some(c), None) if c.is_alphabetic() => {
                    Key::Char(c.to_lowercase().next().unwrap_or(c))
                }
                (Some(c), None) => Key::Char(c),
                _ => Key::Other,
            }
        }
        WinitKey::Named(named) => match named {
            NamedKey::Escape => Key::Escape,
            NamedKey::Enter => Key::Enter,
            NamedKey::Space => Key::Space,
            NamedKey::Tab => Key::Tab,
            NamedKey::Backspace => Key::Backspace,
            NamedKey::Delete => Key::Delete,
            NamedKey::Insert => Key::Insert,
            NamedKey::Home => Key::Home,
            NamedKey::End => Key::End,
            NamedKey::PageUp => Key::PageUp,
            NamedKey::PageDown => Key::PageDown,
            NamedKey::ArrowLeft => Key::Left,
            NamedKey::ArrowRight => Key::Right,
            NamedKey::ArrowUp => Key::Up,
            NamedKey::ArrowDown => Key::Down,
            NamedKey::Shift => Key::Shift,
            NamedKey::Control => Key::Control,
            NamedKey::Alt | NamedKey::AltGraph => Key::Alt,
            NamedKey::Super | NamedKey::Meta => Key::Super,
            f => function_key(*f).map_or(Key::Other, Key::F),
        },
        _ => Key::Other,
    }
}

fn function_key(k: NamedKey) -> Option<u8> {
    use NamedKey::*;
    const KEYS: [NamedKey; 24] = [
        F1, F2, F3, F4, F5, F6, F7, F8, F9, F10, F11, F12, F13, F14, F15, F16, F17, F18, F19, F20,
        F21, F22, F23, F24,
    ];
    KEYS.iter().position(|&f| f == k).map(|i| i as u8 + 1)
}

/// The character a key press typed: the event's text when it is one printable character.
pub(crate) fn typed(text: Option<&str>, state: ElementState) -> Option<char> {
    if state != ElementState::Pressed {
        return None;
    }
    let mut chars = text?.chars();
    match (chars.next(), chars.next()) {
        (Some(c), None) if !c.is_control() || c == ' ' => Some(c),
        _ => None,
    }
}

pub(crate) fn button(b: WinitButton) -> MouseButton {
    match b {
        WinitButton::Left => MouseButton::Left,
        WinitButton::Middle => MouseButton::Middle,
        WinitButton::Right => MouseButton::Right,
        WinitButton::Back => MouseButton::Other(8),
        WinitButton::Forward => MouseButton::Other(9),
        WinitButton::Other(n) => MouseButton::Other(n),
    }
}

pub(crate) fn modifiers(m: winit::keyboard::ModifiersState) -> Modifiers {
    Modifiers {
        shift: m.shift_key(),
        control: m.control_key(),
        alt: m.alt_key(),
        logo: m.super_key(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn letters_are_one_key_whatever_the_case() {
        assert_eq!(key(&WinitKey::Character("A".into())), Key::Char('a'));
        assert_eq!(key(&WinitKey::Character("a".into())), Key::Char('a'));
        assert_eq!(key(&WinitKey::Character("+".into())), Key::Char('+'));
        assert_eq!(key(&WinitKey::Named(NamedKey::F5)), Key::F(5));
        assert_eq!(key(&WinitKey::Named(NamedKey::ArrowUp)), Key::Up);
        assert_eq!(key(&WinitKey::Named(NamedKey::Space)), Key::Space);
    }

    #[test]
    fn typed_characters_keep_their_case_and_only_on_press() {
        assert_eq!(typed(Some("A"), ElementState::Pressed), Some('A'));
        assert_eq!(typed(Some("A"), ElementState::Released), None);
        assert_eq!(typed(Some("\u{1b}"), ElementState::Pressed), None);
        assert_eq!(typed(None, ElementState::Pressed), None);
    }
}
