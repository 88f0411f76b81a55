"""`drive.props`: the property table as attributes.
`drive.props.axis.output_shaft.vel_limit = 300` writes an axis property
(`w axisN.output_shaft.vel_limit 300`), `drive.props.vbus_voltage` reads a
system one; each value travels as its property's type."""


class PropertyTree:
    """One level of the tree: attributes are the next path segments."""

    def __init__(self, drive, table, prefix="", system=True):
        object.__setattr__(self, "_drive", drive)
        object.__setattr__(self, "_prefix", prefix)
        children = {}
        for prop in table.values():
            if prefix == "" and system and not prop.system:
                children["axis"] = None
                continue
            if prop.system != system or not prop.path.startswith(prefix):
                continue
            head, dot, _ = prop.path[len(prefix):].partition(".")
            children[head] = prop if not dot else None
        object.__setattr__(self, "_table", table)
        object.__setattr__(self, "_system", system)
        object.__setattr__(self, "_children", children)

    def _child(self, name):
        children = self._children
        if name not in children:
            raise AttributeError(f"no property {self._prefix}{name}")
        if self._prefix == "" and self._system and name == "axis":
            return None, PropertyTree(self._drive, self._table, "", system=False)
        leaf = children[name]
        if leaf is not None:
            return leaf, None
        return None, PropertyTree(self._drive, self._table, f"{self._prefix}{name}.", self._system)

    def __getattr__(self, name):
        leaf, subtree = self._child(name)
        return subtree if leaf is None else self._drive.get(leaf.path if leaf.system
                                                            else f"axis{self._drive.id}.{leaf.path}")

    def __setattr__(self, name, value):
        leaf, _ = self._child(name)
        if leaf is None:
            raise AttributeError(f"{self._prefix}{name} is a group of properties, not one")
        self._drive.set(leaf.path if leaf.system else f"axis{self._drive.id}.{leaf.path}", value)

    def __dir__(self):
        return sorted(self._children)

    def __repr__(self):
        return f"<properties {self._prefix or '(root)'}: {', '.join(sorted(self._children))}>"
