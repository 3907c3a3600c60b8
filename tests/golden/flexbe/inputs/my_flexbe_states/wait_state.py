"""A state class named WaitState, like flexbe_states' own: import_clash imports both."""
from flexbe_core import EventState


class WaitState(EventState):
    """Returns done at once.

    <= done     Always.
    """

    def __init__(self):
        super(WaitState, self).__init__(outcomes=['done'])

    def execute(self, userdata):
        return 'done'
