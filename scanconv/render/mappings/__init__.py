"""The single-answer formats, each a mapping from the document's block types to output
(:mod:`.text`: markdown and plain, :mod:`.latex`, :mod:`.terminal`: rich, :mod:`.data`: csv and
json, :mod:`.html`: the stepping page), named by :data:`scanconv.render.FORMATS`. (The package
is not called ``formats``: that is :func:`scanconv.render.formats`, which a subpackage of the
same name would shadow once imported.)"""
