# An edited behavior whose [MANUAL_INIT] section lost its closing tag.
class BrokenSM(Behavior):
    def __init__(self, node):
        # [MANUAL_INIT]
        self.x = 1
