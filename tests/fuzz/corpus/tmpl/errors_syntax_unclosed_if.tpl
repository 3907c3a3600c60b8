{% if true %}never closed
