"""Scene.set and Scene.unset that keep the description true: a preset's description names
values ("mu = 0.06"); after set() it gets a note of the keys changed, "[set: surface.mu =
0.1]", in the document too (to_toml()), so it never states a value that was replaced."""

from . import _nanopush

_set, _unset = _nanopush.Scene.set, _nanopush.Scene.unset  # the compiled methods


def _input_error(message, field=""):
    e = _nanopush.InputError(message)
    e.field, e.index = field, None
    return e


_UNSET = object()
_NOTE = "[set: "


def _shown(value):
    value = value.item() if hasattr(value, "item") and getattr(value, "ndim", 1) == 0 else value
    return repr(value) if isinstance(value, float) else str(value)


def _note_changes(scene, changes):
    """Append (or update) the note "[set: key = value; ...]" of the scene's description, so
    the description (and the document, to_toml()) never states a value that set() replaced."""
    desc = scene.description
    base, notes = desc, {}
    i = desc.rfind(_NOTE)
    if i >= 0 and desc.endswith("]"):
        base = desc[:i].rstrip()
        for part in desc[i + len(_NOTE):-1].split("; "):
            k, sep, v = part.partition(" = ")
            if sep:
                notes[k] = v
    notes.update(changes)
    _set(scene, "scene.description",
                  (base + " " if base else "") + _NOTE + "; ".join(f"{k} = {v}" for k, v in notes.items()) + "]")


def _scene_set(self, key, value=_UNSET):
    """Set one key (``set("surface.mu", 0.1)``) or several at once (``set({...})``, validated
    together), validated as the file is; text is read as the key's type. The scene is left
    unchanged when a value is refused (InputError naming key, value and range; a mistyped
    key gets the nearest: "did you mean surface.mu?"). The description gets a note of the
    keys set ("[set: surface.mu = 0.1]"), unless scene.description itself is set."""
    if value is _UNSET:
        if not isinstance(key, dict):
            raise _input_error(f"set({key!r:.80}): give a key and a value, or a dict {{key: value}}", "key")
        _set(self, key)
        changes = {str(k): _shown(v) for k, v in key.items()}
    else:
        _set(self, key, value)
        changes = {str(key): _shown(value)}
    if changes and "scene.description" not in changes:
        _note_changes(self, changes)


def _scene_unset(self, key):
    """Remove a key (back to its default); the scene must stay valid. The description's note
    says so ("[set: surface.mu = (default)]")."""
    _unset(self, key)
    if key != "scene.description":
        _note_changes(self, {str(key): "(default)"})



def keep_description_true(scene_class):
    """Install set and unset on the Scene class (called once by the package)."""
    global _set, _unset
    _set, _unset = scene_class.set, scene_class.unset  # with their signatures (_signatures.methods)
    _scene_set.__qualname__, _scene_unset.__qualname__ = "Scene.set", "Scene.unset"
    scene_class.set, scene_class.unset = _scene_set, _scene_unset
